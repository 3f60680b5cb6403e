#include "support/error_report.hpp"

#include <iostream>

namespace oasis {
namespace {

void report(std::string_view where, std::string_view severity, std::string_view message) {
  std::cerr << report_line(where, severity, message) << std::flush;
}

}  // namespace

std::string report_line(std::string_view where, std::string_view severity,
                        std::string_view message) {
  std::string line;
  line.reserve(where.size() + severity.size() + message.size() + 5);
  line.append(where).append(": ").append(severity).append(": ").append(message).append("\n");
  return line;
}

void report_error(std::string_view where, std::string_view message) {
  report(where, "error", message);
}

void report_warning(std::string_view where, std::string_view message) {
  report(where, "warning", message);
}

void report_note(std::string_view where, std::string_view message) {
  report(where, "note", message);
}

}  // namespace oasis
