#pragma once
// The Python `Catalog`: a binary catalog loaded and checked by the runtime's own loader
// (rt::LoadedCatalog), which owns its bytes; arrays are views into them.

#include <memory>
#include <string>

#include "oasis/rt/catalog_file.hpp"

namespace oasis::python {

struct CatalogObject {
  std::string path;
  rt::LoadedCatalog loaded;
  [[nodiscard]] const rt::CatalogView& view() const { return loaded.view(); }
};

using CatalogPointer = std::shared_ptr<CatalogObject>;

}  // namespace oasis::python
