#pragma once
// The catalog as JSON, for people and tools: the same content as the binary file, with
// names instead of indices where they help (blocks list their member states, policies their
// action names).

#include <nlohmann/json.hpp>

#include "model/catalog_data.hpp"

namespace oasis::codegen {

// Keys: format, name, spec_hash (hex string), compiler_version, states, actions,
// switching, prior, observation, abstractions[] with context, blocks[] ({members, reward,
// action, value}), transitions[] ({block, action, reward, successors: [[block, p], ...]}).
// A row-major n x n matrix as a JSON list of n rows.
nlohmann::json matrix_rows_json(const std::vector<double>& matrix, std::size_t n);

nlohmann::json catalog_json(const model::CatalogData& catalog);

}  // namespace oasis::codegen
