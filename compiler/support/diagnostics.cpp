#include "support/diagnostics.hpp"

#include <ostream>

namespace oasis {
namespace {

constexpr std::size_t kMaxShownColumns = 160;

std::string_view label(Severity severity) {
  switch (severity) {
    case Severity::Error:
      return "error";
    case Severity::Warning:
      return "warning";
    case Severity::Note:
      return "note";
  }
  return "error";
}

bool is_continuation_byte(char c) {
  return (static_cast<unsigned char>(c) & 0xC0U) == 0x80U;
}

// Byte offset of the code point that starts at `column` (1-based) within `line`.
std::size_t byte_of_column(std::string_view line, std::uint32_t column) {
  std::size_t byte = 0;
  for (std::uint32_t c = 1; c < column && byte < line.size();) {
    ++byte;
    if (byte >= line.size() || !is_continuation_byte(line[byte])) ++c;
  }
  return byte;
}

// Prints the source line and a caret under `column`, tildes under the rest of `length`
// bytes. Tabs in the prefix are copied so the caret lines up in any terminal. Very long
// lines (minified or binary input) are cut to a window around the caret.
void print_snippet(std::ostream& out, std::string_view line, std::uint32_t column,
                   std::uint32_t length) {
  std::size_t caret_byte = byte_of_column(line, column);
  std::string_view shown = line;
  std::string_view prefix_mark;
  if (line.size() > kMaxShownColumns) {
    std::size_t start = caret_byte > kMaxShownColumns / 2 ? caret_byte - kMaxShownColumns / 2 : 0;
    while (start > 0 && start < line.size() && is_continuation_byte(line[start]))
      --start;
    std::size_t end = std::min(line.size(), start + kMaxShownColumns);
    while (end < line.size() && is_continuation_byte(line[end]))
      ++end;
    shown = line.substr(start, end - start);
    caret_byte -= start;
    if (start > 0) prefix_mark = "...";
  }
  out << prefix_mark;
  for (char c : shown) {
    // Control characters would move the terminal cursor; show them as '?'.
    const bool control = static_cast<unsigned char>(c) < 0x20 && c != '\t';
    out << (control ? '?' : c);
  }
  out << '\n' << std::string(prefix_mark.size(), ' ');
  for (std::size_t i = 0; i < caret_byte && i < shown.size(); ++i) {
    if (shown[i] == '\t') {
      out << '\t';
    } else if (!is_continuation_byte(shown[i])) {
      out << ' ';
    }
  }
  out << '^';
  std::size_t tilde_end = std::min(shown.size(), caret_byte + length);
  for (std::size_t i = caret_byte + 1; i < tilde_end; ++i) {
    if (!is_continuation_byte(shown[i])) out << '~';
  }
  out << '\n';
}

}  // namespace

DiagnosticEngine::DiagnosticEngine(const SourceManager& sources, std::ostream& out,
                                   std::size_t max_errors)
    : sources_(sources), out_(out), max_errors_(max_errors == 0 ? 1 : max_errors) {}

void DiagnosticEngine::count(Severity severity) {
  if (severity == Severity::Error) ++errors_;
  if (severity == Severity::Warning) ++warnings_;
}

void DiagnosticEngine::emit(Severity severity, SourceRange where, std::string_view message) {
  if (limit_reported_) return;  // past the limit, stay quiet
  count(severity);
  const SourceFile& file = sources_.file(where.begin.file);
  const LineColumn position = file.line_column(where.begin.offset);
  out_ << file.path() << ':' << position.line << ':' << position.column << ": " << label(severity)
       << ": " << message << '\n';
  print_snippet(out_, file.line_text(where.begin.offset), position.column,
                where.length == 0 ? 1 : where.length);
  if (should_stop() && severity == Severity::Error) {
    out_ << "fatal error: too many errors emitted, stopping now\n";
    limit_reported_ = true;
  }
}

void DiagnosticEngine::error(SourceRange where, std::string_view message) {
  emit(Severity::Error, where, message);
}

void DiagnosticEngine::warning(SourceRange where, std::string_view message) {
  emit(Severity::Warning, where, message);
}

void DiagnosticEngine::note(SourceRange where, std::string_view message) {
  emit(Severity::Note, where, message);
}

void DiagnosticEngine::file_error(std::string_view path, std::string_view message) {
  count(Severity::Error);
  out_ << path << ": error: " << message << '\n';
}

void DiagnosticEngine::plain_error(std::string_view message) {
  count(Severity::Error);
  out_ << "oasisc: error: " << message << '\n';
}

}  // namespace oasis
