#pragma once
// One item of a catalog check, as every catalog check reports it: the discrete one
// (discrete_catalog_check.hpp), the continuous one (continuous_check.hpp) and the check of the
// cells a JSON states (stated_cells_check.hpp).

#include <string>

namespace oasis::verify {

struct CatalogCheck {
  std::string item;     // "names", "switching and prior", "context NAME"
  std::string verdict;  // what holds, or why it fails (one sentence)
  bool ok = false;
};

}  // namespace oasis::verify
