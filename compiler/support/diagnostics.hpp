#pragma once
// The one diagnostic engine of oasisc. Every message has the clang shape
//
//   file:line:col: error: message
//   <the source line>
//           ^~~~
//
// Messages are lower-case fragments without a final period. Errors are printed as they are
// reported, so a long run shows problems early; after `max_errors` the engine asks callers to
// stop (`should_stop()`), which keeps a badly broken file from flooding the terminal.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <string>
#include <string_view>

#include "support/source_manager.hpp"

namespace oasis {

enum class Severity { Error, Warning, Note };

// "error", "warning" or "note": the word a diagnostic is printed with.
std::string_view severity_label(Severity severity);

// A located span: the caret goes under `begin`, tildes under the rest of the span.
struct SourceRange {
  SourceLocation begin;
  std::uint32_t length = 1;
};

// The span from the start of `first` to the end of `last` (same file); `first` alone when
// `last` starts before it. A span longer than 2^32 - 1 bytes is cut there: it is underlined
// on one line, which is far shorter.
inline SourceRange span(SourceRange first, SourceRange last) {
  if (last.begin.offset < first.begin.offset) return first;
  const SourceOffset end = last.begin.offset + last.length;
  const SourceOffset length = end > first.begin.offset ? end - first.begin.offset : 1;
  return {first.begin, static_cast<std::uint32_t>(std::min<SourceOffset>(length, UINT32_MAX))};
}

// A diagnostic as data, for callers that keep them besides the printed text (the Python
// module's SpecError.diagnostics). `line` and `column` are 0 for a file's error at no place in
// it, and `file` is empty for an error of no file.
struct DiagnosticRecord {
  Severity severity = Severity::Error;
  std::string file;
  std::uint64_t line = 0;
  std::uint32_t column = 0;
  std::string message;
};

class DiagnosticEngine {
 public:
  DiagnosticEngine(const SourceManager& sources, std::ostream& out, std::size_t max_errors = 20);

  void error(SourceRange where, std::string_view message);
  void warning(SourceRange where, std::string_view message);
  void note(SourceRange where, std::string_view message);
  void error(SourceLocation where, std::string_view message) {
    error(SourceRange{where, 1}, message);
  }
  void note(SourceLocation where, std::string_view message) {
    note(SourceRange{where, 1}, message);
  }

  // For problems that belong to a file but to no place in it (cannot open, too large).
  void file_error(std::string_view path, std::string_view message);
  // The same for a warning (a binary file's doubtful value): "PATH: warning: ...".
  void file_warning(std::string_view path, std::string_view message);
  // For problems that belong to no file (bad command-line values): "PROGRAM: error: ...".
  void plain_error(std::string_view message);

  [[nodiscard]] std::size_t error_count() const { return errors_; }
  [[nodiscard]] std::size_t warning_count() const { return warnings_; }
  [[nodiscard]] bool has_errors() const { return errors_ > 0; }
  // True once the error limit is reached: callers finish the current unit and return.
  [[nodiscard]] bool should_stop() const { return errors_ >= max_errors_; }

  [[nodiscard]] const SourceManager& sources() const { return sources_; }

  // Also hands every diagnostic that is printed to `listener` (none by default).
  void set_listener(std::function<void(const DiagnosticRecord&)> listener) {
    listener_ = std::move(listener);
  }

 private:
  void emit(Severity severity, SourceRange where, std::string_view message);
  void count(Severity severity);

  const SourceManager& sources_;
  std::ostream& out_;
  std::size_t max_errors_;
  std::size_t errors_ = 0;
  std::size_t warnings_ = 0;
  bool limit_reported_ = false;
  std::function<void(const DiagnosticRecord&)> listener_;
};

}  // namespace oasis
