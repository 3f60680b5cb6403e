#pragma once
// How the module fails: every error leaves as an exception of the package's own hierarchy
// (oasis/errors.py), never as a crash or a message on the terminal. C++ code, on any thread,
// throws a Failure; pybind11's translator turns it into the Python exception once the call is
// back on the thread that holds the GIL. Diagnostics of the compiler's one engine are kept as
// text (the exception's message, as oasisc would print it) and as records (.diagnostics).

#include <cstddef>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>

#include "support/diagnostics.hpp"
#include "support/source_manager.hpp"

namespace oasis::python {

// The exception classes of oasis/errors.py.
enum class ErrorKind { kError, kSpec, kProperty, kCatalog, kCompile, kFilter, kExactLimit };

class Failure : public std::runtime_error {
 public:
  Failure(ErrorKind kind, const std::string& message,
          std::vector<DiagnosticRecord> diagnostics = {})
      : std::runtime_error(message), kind_(kind), diagnostics_(std::move(diagnostics)) {}
  [[nodiscard]] ErrorKind kind() const { return kind_; }
  [[nodiscard]] const std::vector<DiagnosticRecord>& diagnostics() const { return diagnostics_; }

 private:
  ErrorKind kind_;
  std::vector<DiagnosticRecord> diagnostics_;
};

// The diagnostics of one call: the files it read, the engine, the printed text and the records.
class Diagnostics {
 public:
  explicit Diagnostics(std::size_t max_errors = 20);
  Diagnostics(const Diagnostics&) = delete;
  Diagnostics& operator=(const Diagnostics&) = delete;

  [[nodiscard]] SourceManager& sources() { return sources_; }
  [[nodiscard]] DiagnosticEngine& engine() { return engine_; }
  [[nodiscard]] bool has_errors() const { return engine_.has_errors(); }
  // Throws a Failure of `kind` with what was reported; `fallback` when nothing was.
  [[noreturn]] void fail(ErrorKind kind, const std::string& fallback) const;
  template <typename Predicate>
  [[nodiscard]] bool any_message(Predicate&& predicate) const {
    for (const DiagnosticRecord& record : records_)
      if (predicate(record.message)) return true;
    return false;
  }

 private:
  SourceManager sources_;
  std::ostringstream text_;
  std::vector<DiagnosticRecord> records_;
  DiagnosticEngine engine_;
};

void bind_errors(pybind11::module_& module);

}  // namespace oasis::python
