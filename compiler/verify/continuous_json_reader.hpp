#pragma once
// Reading a continuous catalog's JSON (codegen/continuous_json.hpp, the contract tools
// outside the project read) back into the runtime's schema, so that `oasisc verify SPEC
// NAME.json` checks the JSON as it checks the binary file. Only the shape is checked here
// (keys present, of the right types, names known); what the numbers mean is checked by
// rt::validate and the verifier. The polytope each cell states (A x <= b) is read for the
// verifier too (verify/stated_cells_check.hpp), when the caller asks for it.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "model/catalog_data.hpp"
#include "verify/stated_cells_check.hpp"

namespace oasis::verify {

// Per abstraction, the cells as the JSON states them.
using StatedCells = std::vector<std::vector<StatedCell>>;

// nullopt with `error` (one sentence, without the path) when the file is not such a JSON or
// is larger than `max_bytes`. With `stated`, also each cell's stated polytope.
std::optional<model::CatalogData> read_continuous_catalog_json(const std::string& path,
                                                               std::size_t max_bytes,
                                                               std::string& error,
                                                               StatedCells* stated = nullptr);
// The same on the file's text.
std::optional<model::CatalogData> parse_continuous_catalog_json(std::string_view text,
                                                                std::string& error,
                                                                StatedCells* stated = nullptr);

}  // namespace oasis::verify
