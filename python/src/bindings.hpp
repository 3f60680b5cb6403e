#pragma once
// The parts of the module, one concept per file, each adding its classes and functions.

#include <cstdint>
#include <optional>
#include <string>

#include <pybind11/pybind11.h>

namespace oasis::python {

void bind_model(pybind11::module_& module);         // model_object.cpp
void bind_loading(pybind11::module_& module);       // loading.cpp
void bind_bisimulation(pybind11::module_& module);  // bisimulation.cpp
void bind_check(pybind11::module_& module);         // checking.cpp
void bind_compile(pybind11::module_& module);       // compiling.cpp
void bind_catalog(pybind11::module_& module);       // catalog.cpp
void bind_filter(pybind11::module_& module);        // filter.cpp

// Catalog.load: the binary catalog at `path`, checked as the runtime checks it.
pybind11::object load_catalog(const std::string& path, std::optional<std::uint64_t> spec_hash);

}  // namespace oasis::python
