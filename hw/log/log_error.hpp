#pragma once
// The one exception type of the step log: a file that cannot be opened or written, a line that
// is not a step record. Its message is "FILE:LINE: error: message" (FILE alone when no line is
// involved), the format of every oasis diagnostic, so that editors can jump to the line.

#include <cstddef>
#include <stdexcept>
#include <string>

namespace oasis::hw::log {

class LogError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// "FILE:LINE: error: message"; line 0 means the file as a whole: "FILE: error: message".
std::string log_diagnostic(const std::string& file, std::size_t line, const std::string& severity,
                           const std::string& message);

}  // namespace oasis::hw::log
