// Catalog.load: a binary catalog read as a robot reads it (rt::LoadedCatalog::from_file: magic,
// format, checksum, bounds, then validate()), optionally refused when compiled from another
// spec. What it carries is exposed read-only, arrays as zero-copy views.

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "arrays.hpp"
#include "bindings.hpp"
#include "catalog_object.hpp"
#include "errors.hpp"
#include "oasis/rt/spec_hash.hpp"

namespace oasis::python {
namespace py = pybind11;

namespace {

const rt::AbstractionView& abstraction(const CatalogObject& catalog, std::uint32_t i) {
  if (i >= catalog.view().num_abstractions) {
    throw py::index_error("abstraction " + std::to_string(i) + " out of range (the catalog has " +
                          std::to_string(catalog.view().num_abstractions) + ")");
  }
  return catalog.view().abstractions[i];
}

std::vector<std::string> names(const char* const* array, std::size_t count) {
  std::vector<std::string> result;
  if (array == nullptr) return result;
  for (std::size_t i = 0; i < count; ++i)
    result.emplace_back(array[i]);
  return result;
}

py::dict abstraction_dict(const py::object& self, std::uint32_t i) {
  const auto& catalog = self.cast<const CatalogObject&>();
  const rt::AbstractionView& a = abstraction(catalog, i);
  const rt::CatalogView& view = catalog.view();
  py::dict result;
  result["context"] = std::string(a.context);
  result["nr_blocks"] = a.num_blocks;
  result["block_of"] = a.block_of == nullptr
                           ? py::object(py::none())
                           : py::object(python::view(a.block_of, view.num_states, self));
  result["block_reward"] = python::view(a.block_reward, a.num_blocks, self);
  result["policy"] = python::view(a.policy, a.num_blocks, self);
  result["value"] = python::view(a.value, a.num_blocks, self);
  result["reward"] = python::view(a.reward, a.num_blocks, view.num_actions, self);
  return result;
}

}  // namespace

py::object load_catalog(const std::string& path, std::optional<std::uint64_t> spec_hash) {
  auto catalog = std::make_shared<CatalogObject>();
  catalog->path = path;
  {
    const py::gil_scoped_release release;  // reading and checking a large file
    catalog->loaded = spec_hash ? rt::LoadedCatalog::from_file(path, *spec_hash)
                                : rt::LoadedCatalog::from_file(path);
  }
  if (!catalog->loaded.ok()) throw Failure(ErrorKind::kCatalog, catalog->loaded.error());
  return py::cast(catalog);
}

void bind_catalog(py::module_& module) {
  py::class_<CatalogObject, CatalogPointer>(
      module, "Catalog",
      "A compiled catalog of abstractions, loaded and checked as the runtime loads it.")
      .def_static(
          "load",
          [](const std::string& path, std::optional<std::uint64_t> spec_hash) {
            return load_catalog(path, spec_hash);
          },
          py::arg("path"), py::arg("spec_hash") = py::none(),
          "Loads NAME.bin: checks its magic, format, checksum, every section's bounds and the "
          "catalog's invariants (rt::LoadedCatalog::from_file). With spec_hash, also refuses a "
          "catalog compiled from another spec. Raises CatalogError saying why.")
      .def_readonly("path", &CatalogObject::path)
      .def_property_readonly("name",
                             [](const CatalogObject& c) { return std::string(c.view().name); })
      .def_property_readonly(
          "spec_hash", [](const CatalogObject& c) { return c.view().spec_hash; },
          "rt::spec_hash of the spec it was compiled from.")
      .def_property_readonly(
          "compiler_version",
          [](const CatalogObject& c) { return std::string(c.view().compiler_version); })
      .def_property_readonly("nr_states",
                             [](const CatalogObject& c) { return c.view().num_states; })
      .def_property_readonly("nr_actions",
                             [](const CatalogObject& c) { return c.view().num_actions; })
      .def_property_readonly(
          "actions",
          [](const CatalogObject& c) { return names(c.view().action_names, c.view().num_actions); })
      .def_property_readonly(
          "state_names",
          [](const CatalogObject& c) { return names(c.view().state_names, c.view().num_states); })
      .def_property_readonly("nr_abstractions",
                             [](const CatalogObject& c) { return c.view().num_abstractions; })
      .def_property_readonly("contexts",
                             [](const CatalogObject& c) {
                               std::vector<std::string> result;
                               for (std::uint32_t i = 0; i < c.view().num_abstractions; ++i)
                                 result.emplace_back(c.view().abstractions[i].context);
                               return result;
                             })
      .def_property_readonly("is_continuous",
                             [](const CatalogObject& c) { return c.view().is_continuous(); })
      .def_property_readonly(
          "has_robust_section",
          [](const CatalogObject& c) { return c.view().has_robust_section(); },
          "Whether the joint and hedged filters can run on it.")
      .def_property_readonly(
          "switching",
          [](const py::object& self) {
            const rt::CatalogView& v = self.cast<const CatalogObject&>().view();
            return view(v.switching, v.num_abstractions, v.num_abstractions, self);
          },
          "p(phi_t = j | phi_{t-1} = i) as an N x N read-only view.")
      .def_property_readonly(
          "prior",
          [](const py::object& self) {
            const rt::CatalogView& v = self.cast<const CatalogObject&>().view();
            return view(v.prior, v.num_abstractions, self);
          },
          "p(phi_0) as a read-only view.")
      .def("abstraction", &abstraction_dict, py::arg("index"),
           "Abstraction `index`: its context, nr_blocks, and read-only views of block_of, "
           "block_reward, policy, value and reward (nr_blocks x nr_actions).")
      .def("__repr__", [](const CatalogObject& c) {
        return "<oasis.Catalog '" + std::string(c.view().name) + "' " +
               std::to_string(c.view().num_abstractions) + " abstractions>";
      });
  module.def(
      "spec_hash", [](const py::bytes& text) { return rt::spec_hash(std::string(text)); },
      py::arg("text"), "rt::spec_hash (FNV-1a 64) of a spec's bytes, as a catalog records it.");
}

}  // namespace oasis::python
