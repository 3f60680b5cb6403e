#include "log/log_error.hpp"

#include "text/printable_text.hpp"

namespace oasis::hw::log {

std::string log_diagnostic(const std::string& file, std::size_t line, const std::string& severity,
                           const std::string& message) {
  std::string text = file;
  if (line > 0) text += ":" + std::to_string(line);
  // The message may quote the log's own bytes (a 10 MB number, a NUL): escaped and cut.
  return text + ": " + severity + ": " + oasis::text::printable_message(message);
}

}  // namespace oasis::hw::log
