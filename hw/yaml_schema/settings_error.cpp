#include "yaml_schema/settings_error.hpp"

#include <algorithm>
#include <string>
#include <utility>

#include "text/printable_text.hpp"

namespace oasis::hw::yaml_schema {

namespace {

std::string join_formatted(const std::string& file, const std::vector<Diagnostic>& diagnostics) {
  std::string text;
  for (const Diagnostic& diagnostic : diagnostics) {
    if (!text.empty()) text += '\n';
    text += format_diagnostic(file, diagnostic);
  }
  return text;
}

// Positioned problems first, in file order; those without a place keep their order at the end.
std::vector<Diagnostic> in_file_order(std::vector<Diagnostic> diagnostics) {
  std::stable_sort(diagnostics.begin(), diagnostics.end(),
                   [](const Diagnostic& a, const Diagnostic& b) {
                     if ((a.line == 0) != (b.line == 0)) return b.line == 0;
                     if (a.line != b.line) return a.line < b.line;
                     return a.column < b.column;
                   });
  return diagnostics;
}

}  // namespace

std::string format_diagnostic(const std::string& file, const Diagnostic& diagnostic) {
  std::string text = file;
  if (diagnostic.line > 0)
    text += ":" + std::to_string(diagnostic.line) + ":" + std::to_string(diagnostic.column);
  text += ": error: ";
  if (!diagnostic.key.empty()) text += diagnostic.key + ": ";
  text += oasis::text::printable_message(diagnostic.message);
  if (diagnostic.line > 0 && !diagnostic.source_line.empty()) {
    // A window of a long line around the caret, control bytes replaced (a YAML line can be a
    // megabyte long, or hold a NUL).
    const auto column = static_cast<std::size_t>(std::max(diagnostic.column - 1, 0));
    const oasis::text::SourceWindow window =
        oasis::text::source_window(diagnostic.source_line, column);
    const std::string prefix = window.cut_before ? "..." : "";
    text += "\n  " + prefix + window.text + "\n  " + std::string(prefix.size(), ' ');
    // Tabs stay tabs so that the caret lines up however the terminal draws them.
    for (std::size_t i = 0; i < window.caret && i < window.text.size(); ++i)
      text += window.text[i] == '\t' ? '\t' : ' ';
    text += '^';
  }
  return text;
}

SettingsError::SettingsError(std::string file, std::vector<Diagnostic> diagnostics)
    : std::runtime_error(join_formatted(file, in_file_order(diagnostics))),
      file_(std::move(file)),
      diagnostics_(in_file_order(std::move(diagnostics))) {}

}  // namespace oasis::hw::yaml_schema
