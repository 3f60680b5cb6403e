#include "log/log_error.hpp"

namespace oasis::hw::log {

std::string log_diagnostic(const std::string& file, std::size_t line, const std::string& severity,
                           const std::string& message) {
  std::string text = file;
  if (line > 0) text += ":" + std::to_string(line);
  return text + ": " + severity + ": " + message;
}

}  // namespace oasis::hw::log
