// The module `oasis._oasis`, which oasis/__init__.py re-exports (docs/python.md).

#include <pybind11/pybind11.h>

#include "bindings.hpp"
#include "errors.hpp"

PYBIND11_MODULE(_oasis, module) {
  module.doc() = "oasis: the abstraction compiler and runtime for Online Attention Switching";
  module.attr("__version__") = OASIS_PYTHON_VERSION;
  oasis::python::bind_errors(module);
  oasis::python::bind_model(module);
  oasis::python::bind_loading(module);
  oasis::python::bind_bisimulation(module);
  oasis::python::bind_check(module);
  oasis::python::bind_compile(module);
  oasis::python::bind_catalog(module);
  oasis::python::bind_filter(module);
}
