#include "support/diagnostics.hpp"

#include <algorithm>
#include <cerrno>
#include <ostream>
#include <string>

#include "support/error_report.hpp"
#include "text/printable_text.hpp"

namespace oasis {

std::string_view severity_label(Severity severity) {
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

namespace {

// Byte offset of the code point that starts at `column` (1-based) within `line`.
std::size_t byte_of_column(std::string_view line, std::uint32_t column) {
  std::size_t byte = 0;
  for (std::uint32_t c = 1; c < column && byte < line.size();) {
    ++byte;
    if (byte >= line.size() || !text::is_continuation_byte(line[byte])) ++c;
  }
  return byte;
}

// Prints the source line and a caret under `column`, tildes under the rest of `length`
// bytes. Tabs in the prefix are copied so the caret lines up in any terminal. Very long
// lines (minified or binary input) are cut to a window around the caret.
void print_snippet(std::ostream& out, std::string_view line, std::uint32_t column,
                   std::uint32_t length) {
  const text::SourceWindow window = text::source_window(line, byte_of_column(line, column));
  const std::string_view shown = window.text;
  const std::string_view prefix_mark = window.cut_before ? "..." : "";
  out << prefix_mark << shown << '\n' << std::string(prefix_mark.size(), ' ');
  for (std::size_t i = 0; i < window.caret && i < shown.size(); ++i) {
    if (shown[i] == '\t') {
      out << '\t';
    } else if (!text::is_continuation_byte(shown[i])) {
      out << ' ';
    }
  }
  out << '^';
  const std::size_t tilde_end = std::min<std::size_t>(shown.size(), window.caret + length);
  for (std::size_t i = window.caret + 1; i < tilde_end; ++i) {
    if (!text::is_continuation_byte(shown[i])) out << '~';
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
  out_ << file.path() << ':' << position.line << ':' << position.column << ": "
       << severity_label(severity) << ": " << text::printable_message(message) << '\n';
  if (listener_) {
    listener_(
        {severity, file.path(), position.line, position.column, text::printable_message(message)});
  }
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
  out_ << report_line(path, "error", text::printable_message(message));
  if (listener_)
    listener_({Severity::Error, std::string(path), 0, 0, text::printable_message(message)});
}

void DiagnosticEngine::file_warning(std::string_view path, std::string_view message) {
  count(Severity::Warning);
  out_ << report_line(path, "warning", text::printable_message(message));
  if (listener_) {
    listener_({Severity::Warning, std::string(path), 0, 0, text::printable_message(message)});
  }
}

void DiagnosticEngine::plain_error(std::string_view message) {
  count(Severity::Error);
  // The program that runs (oasisc, oasisc-mpi, oasis-sim), as its other messages name it.
  out_ << report_line(program_invocation_short_name, "error", text::printable_message(message));
  if (listener_) listener_({Severity::Error, {}, 0, 0, text::printable_message(message)});
}

}  // namespace oasis
