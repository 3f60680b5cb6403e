#include "errors.hpp"

namespace oasis::python {
namespace py = pybind11;

namespace {

const char* class_name(ErrorKind kind) {
  switch (kind) {
    case ErrorKind::kError:
      return "Error";
    case ErrorKind::kSpec:
      return "SpecError";
    case ErrorKind::kProperty:
      return "PropertyError";
    case ErrorKind::kCatalog:
      return "CatalogError";
    case ErrorKind::kCompile:
      return "CompileError";
    case ErrorKind::kFilter:
      return "FilterError";
    case ErrorKind::kExactLimit:
      return "ExactLimitError";
  }
  return "Error";
}

// Sets the Python exception for `failure`. Runs inside pybind11's translator, which must not
// throw: if the package's classes cannot be reached, a RuntimeError says what failed.
void raise(const Failure& failure) {
  try {
    const py::module_ errors = py::module_::import("oasis.errors");
    const py::object diagnostic = errors.attr("Diagnostic");
    py::list records;
    for (const DiagnosticRecord& record : failure.diagnostics()) {
      records.append(diagnostic(record.file, record.line, record.column,
                                std::string(severity_label(record.severity)), record.message));
    }
    const py::object type = errors.attr(class_name(failure.kind()));
    const py::object instance = type(failure.what(), records);
    PyErr_SetObject(type.ptr(), instance.ptr());
  } catch (py::error_already_set& error) {
    error.restore();
  }
}

}  // namespace

Diagnostics::Diagnostics(std::size_t max_errors) : engine_(sources_, text_, max_errors) {
  engine_.set_listener([this](const DiagnosticRecord& record) { records_.push_back(record); });
}

void Diagnostics::fail(ErrorKind kind, const std::string& fallback) const {
  std::string text = text_.str();
  while (!text.empty() && text.back() == '\n')
    text.pop_back();
  throw Failure(kind, text.empty() ? fallback : text, records_);
}

void bind_errors(py::module_& module) {
  static_cast<void>(module);
  // By value: pybind11's translator is a function pointer of that type.
  // NOLINTNEXTLINE(performance-unnecessary-value-param)
  py::register_exception_translator([](std::exception_ptr pointer) {
    try {
      if (pointer) std::rethrow_exception(pointer);
    } catch (const Failure& failure) {
      raise(failure);
    }
  });
}

}  // namespace oasis::python
