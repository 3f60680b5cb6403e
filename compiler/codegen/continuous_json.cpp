#include "codegen/continuous_json.hpp"

#include "codegen/json_catalog.hpp"
#include "oasis/rt/catalog_view.hpp"
#include "pipeline/catalog_data.hpp"

namespace oasis::codegen {
namespace {

// A box cell as A x <= b: x_i <= high_i and -x_i <= -low_i for every relevant variable.
nlohmann::json cell_json(const geom::Grid& grid, const std::vector<std::uint32_t>& index,
                         std::uint32_t block) {
  const std::size_t d = grid.dimension();
  nlohmann::json a = nlohmann::json::array();
  nlohmann::json b = nlohmann::json::array();
  for (std::size_t i = 0; i < d; ++i) {
    std::vector<int> upper(d, 0);
    std::vector<int> lower(d, 0);
    upper[i] = 1;
    lower[i] = -1;
    a.push_back(upper);
    b.push_back(grid.breaks_double(i)[index[i] + 1]);
    a.push_back(lower);
    b.push_back(-grid.breaks_double(i)[index[i]]);
  }
  return {{"A", std::move(a)}, {"b", std::move(b)}, {"block", block}};
}

nlohmann::json next_json(const pipeline::ContinuousAbstraction& abstraction,
                         const std::vector<std::string>& actions, std::uint32_t block) {
  const model::TransitionMatrix& matrix = *abstraction.quotient.contexts[0].transitions;
  nlohmann::json next = nlohmann::json::object();
  for (model::ActionIndex a = 0; a < actions.size(); ++a) {
    nlohmann::json row = nlohmann::json::array();
    for (auto e = matrix.edges_begin(block, a); e < matrix.edges_end(block, a); ++e) {
      row.push_back(nlohmann::json::array(
          {matrix.edge_target[e],
           to_double(abstraction.quotient.values[matrix.edge_probability[e]])}));
    }
    next[actions[a]] = std::move(row);
  }
  return next;
}

nlohmann::json abstraction_json(const pipeline::ContinuousCatalog& catalog,
                                const pipeline::ContinuousAbstraction& abstraction,
                                bool with_transitions) {
  nlohmann::json out;
  out["context"] = abstraction.context;
  out["relevant_variables"] = abstraction.axis_names;
  out["epsilon"] = to_double(abstraction.epsilon);
  out["exact"] = abstraction.exact();
  out["num_blocks"] = abstraction.num_blocks;
  out["outside_block"] = abstraction.outside_block;
  nlohmann::json grid = nlohmann::json::array();
  for (std::size_t i = 0; i < abstraction.grid.dimension(); ++i)
    grid.push_back(abstraction.grid.breaks_double(i));
  out["grid"] = std::move(grid);
  nlohmann::json cells = nlohmann::json::array();
  std::vector<std::uint32_t> index(abstraction.grid.dimension());
  for (std::size_t cell = 0; cell < abstraction.grid.num_cells(); ++cell) {
    abstraction.grid.index_of(cell, index);
    cells.push_back(cell_json(abstraction.grid, index, abstraction.cell_block[cell]));
  }
  out["cells"] = std::move(cells);
  nlohmann::json blocks = nlohmann::json::array();
  for (std::uint32_t z = 0; z < abstraction.num_blocks; ++z) {
    const std::uint32_t action = abstraction.policy[z];
    nlohmann::json block{
        {"reward", abstraction.block_reward[z]},
        {"policy",
         action == rt::kNoAction ? nlohmann::json() : nlohmann::json(catalog.action_names[action])},
        {"value", abstraction.value[z]}};
    if (with_transitions) block["next"] = next_json(abstraction, catalog.action_names, z);
    blocks.push_back(std::move(block));
  }
  out["blocks"] = std::move(blocks);
  return out;
}

}  // namespace

nlohmann::json continuous_catalog_json(const pipeline::ContinuousCatalog& catalog,
                                       bool with_transitions) {
  nlohmann::json out;
  out["format"] = rt::kCatalogFormat;
  out["name"] = catalog.name;
  out["spec_hash"] = pipeline::hash_text(catalog.spec_hash);
  out["compiler_version"] = catalog.compiler_version;
  out["variables"] = catalog.variable_names;
  out["actions"] = catalog.action_names;
  out["switching"] = matrix_rows_json(catalog.switching, catalog.abstractions.size());
  out["prior"] = catalog.prior;
  nlohmann::json abstractions = nlohmann::json::array();
  for (const pipeline::ContinuousAbstraction& abstraction : catalog.abstractions)
    abstractions.push_back(abstraction_json(catalog, abstraction, with_transitions));
  out["abstractions"] = std::move(abstractions);
  return out;
}

}  // namespace oasis::codegen
