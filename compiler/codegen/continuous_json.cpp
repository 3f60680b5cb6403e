#include "codegen/continuous_json.hpp"

#include "codegen/json_catalog.hpp"
#include "model/catalog_data.hpp"
#include "oasis/rt/catalog_view.hpp"
#include "oasis/rt/spec_hash.hpp"
#include "pipeline/continuous_catalog_data.hpp"

namespace oasis::codegen {
namespace {

// A box cell as A x <= b: x_i <= high_i and -x_i <= -low_i for every relevant variable.
void write_cell(JsonWriter& out, const pipeline::CellPartition& grid,
                const std::vector<std::uint32_t>& index, std::uint32_t block) {
  const std::size_t d = grid.dimension();
  out.begin_object();
  out.key("A");
  out.begin_array();
  for (std::size_t i = 0; i < d; ++i) {
    for (const int sign : {1, -1}) {
      out.begin_array();
      for (std::size_t j = 0; j < d; ++j)
        out.value(static_cast<double>(j == i ? sign : 0));
      out.end_array();
    }
  }
  out.end_array();
  out.key("b");
  out.begin_array();
  for (std::size_t i = 0; i < d; ++i) {
    out.value(grid.breaks[i][index[i] + 1]);
    out.value(-grid.breaks[i][index[i]]);
  }
  out.end_array();
  out.key("block");
  out.value(block);
  out.end_object();
}

// A polytope cell as A x <= b: its irredundant constraints, rounded to nearest doubles.
void write_polytope_cell(JsonWriter& out, const pipeline::PolytopeCell& cell, std::uint32_t block) {
  out.begin_object();
  out.key("A");
  out.begin_array();
  for (const std::vector<double>& row : cell.rows) {
    out.begin_array();
    for (const double a : row)
      out.value(a);
    out.end_array();
  }
  out.end_array();
  out.key("b");
  out.begin_array();
  for (const double bound : cell.bounds)
    out.value(bound);
  out.end_array();
  out.key("block");
  out.value(block);
  out.end_object();
}

// The BSP as the runtime walks it (rt::BspView): per node its rounded half-space a.x <= c,
// its children, and the cell of a leaf (null for an internal node).
void write_bsp(JsonWriter& out, const pipeline::BspArrays& bsp) {
  out.begin_object();
  out.key("normal");
  out.begin_array();
  for (std::size_t node = 0; node < bsp.num_nodes(); ++node) {
    const auto first = bsp.normal.begin() + static_cast<std::ptrdiff_t>(node * bsp.dimension);
    out.embed(bsp.is_leaf(node)
                  ? nlohmann::json::array()
                  : nlohmann::json(std::vector<double>(first, first + bsp.dimension)));
  }
  out.end_array();
  const auto field = [&](const char* name, const auto& get) {
    out.key(name);
    out.begin_array();
    for (std::size_t node = 0; node < bsp.num_nodes(); ++node)
      get(node);
    out.end_array();
  };
  field("bound", [&](std::size_t node) { out.value(bsp.bound[node]); });
  field("below", [&](std::size_t node) { out.value(bsp.below[node]); });
  field("above", [&](std::size_t node) { out.value(bsp.above[node]); });
  field("cell", [&](std::size_t node) {
    if (bsp.is_leaf(node)) {
      out.value(bsp.cell[node]);
    } else {
      out.null();
    }
  });
  out.end_object();
}

void write_next(JsonWriter& out, const pipeline::ContinuousAbstraction& abstraction,
                const std::vector<std::string>& actions, const std::vector<double>& probability,
                std::uint32_t block) {
  const model::TransitionMatrix& matrix = *abstraction.quotient.contexts[0].transitions;
  out.begin_object();
  for (model::ActionIndex a = 0; a < actions.size(); ++a) {
    out.key(actions[a]);
    out.begin_array();
    for (auto e = matrix.edges_begin(block, a); e < matrix.edges_end(block, a); ++e) {
      out.begin_array();
      out.value(matrix.edge_target[e]);
      out.value(probability[matrix.edge_probability[e]]);
      out.end_array();
    }
    out.end_array();
  }
  out.end_object();
}

void write_blocks(JsonWriter& out, const pipeline::ContinuousCatalog& catalog,
                  const pipeline::ContinuousAbstraction& abstraction, bool with_transitions) {
  const std::vector<double> probability =
      with_transitions ? model::value_doubles(abstraction.quotient) : std::vector<double>{};
  out.begin_array();
  for (std::uint32_t z = 0; z < abstraction.num_blocks; ++z) {
    const std::uint32_t action = abstraction.policy[z];
    out.begin_object();
    out.key("reward");
    out.value(abstraction.block_reward[z]);
    out.key("policy");
    if (action == rt::kNoAction) {
      out.null();
    } else {
      out.value(catalog.action_names[action]);
    }
    out.key("value");
    out.value(abstraction.value[z]);
    if (with_transitions) {
      out.key("next");
      write_next(out, abstraction, catalog.action_names, probability, z);
    }
    out.end_object();
  }
  out.end_array();
}

void write_abstraction(JsonWriter& out, const pipeline::ContinuousCatalog& catalog,
                       const pipeline::ContinuousAbstraction& abstraction, bool with_transitions) {
  out.begin_object();
  out.key("context");
  out.value(abstraction.context);
  out.key("relevant_variables");
  out.embed(nlohmann::json(abstraction.axis_names));
  out.key("epsilon");  // rounded up: a bound must never be understated
  out.value(pipeline::bound_as_double(abstraction.epsilon));
  out.key("exact");
  out.value(abstraction.exact());
  out.key("num_blocks");
  out.value(abstraction.num_blocks);
  out.key("outside_block");
  out.value(abstraction.outside_block);
  out.key("grid");
  out.begin_array();
  for (const std::vector<double>& breaks : abstraction.cells.breaks)
    out.embed(nlohmann::json(breaks));
  out.end_array();
  if (abstraction.cells.bsp) {
    out.key("bsp");
    write_bsp(out, *abstraction.cells.bsp);
  }
  out.key("cells");
  out.begin_array();
  if (abstraction.cells.bsp) {
    for (std::size_t cell = 0; cell < abstraction.cells.polytopes.size(); ++cell)
      write_polytope_cell(out, abstraction.cells.polytopes[cell], abstraction.cell_block[cell]);
  } else {
    std::vector<std::uint32_t> index(abstraction.cells.dimension());
    for (std::size_t cell = 0; cell < abstraction.cells.num_cells(); ++cell) {
      abstraction.cells.index_of(cell, index);
      write_cell(out, abstraction.cells, index, abstraction.cell_block[cell]);
    }
  }
  out.end_array();
  out.key("blocks");
  write_blocks(out, catalog, abstraction, with_transitions);
  out.end_object();
}

// null without an observation block; else what the reward follows and the objects the
// sensor measures: their variables, sigma(d) coefficients [a, b, c] and detection probability.
nlohmann::json observation_json(const pipeline::ContinuousCatalog& catalog) {
  const model::PositionNoiseData& noise = catalog.position;
  if (noise.empty() && catalog.reward_source == rt::RewardSource::kTrueState) return nullptr;
  nlohmann::json objects = nlohmann::json::array();
  for (std::size_t k = 0; k < noise.detection.size(); ++k) {
    std::vector<std::string> variables;
    for (std::size_t v = 0; v < noise.object_of.size(); ++v)
      if (noise.object_of[v] == k) variables.push_back(catalog.variable_names[v]);
    objects.push_back(
        {{"name", noise.object_names[k]},
         {"variables", variables},
         {"sigma", {noise.sigma[3 * k], noise.sigma[3 * k + 1], noise.sigma[3 * k + 2]}},
         {"detection", noise.detection[k]}});
  }
  return {{"reward_follows",
           catalog.reward_source == rt::RewardSource::kObservedState ? "observed" : "true"},
          {"objects", std::move(objects)}};
}

}  // namespace

void write_continuous_catalog_json(JsonWriter& out, const pipeline::ContinuousCatalog& catalog,
                                   bool with_transitions) {
  out.begin_object();
  out.key("format");
  out.value(std::uint64_t{rt::kCatalogFormat});
  out.key("name");
  out.value(catalog.name);
  out.key("spec_hash");
  out.value(rt::spec_hash_text(catalog.spec_hash));
  out.key("compiler_version");
  out.value(catalog.compiler_version);
  out.key("variables");
  out.embed(nlohmann::json(catalog.variable_names));
  out.key("actions");
  out.embed(nlohmann::json(catalog.action_names));
  out.key("switching");
  out.embed(matrix_rows_json(catalog.switching, catalog.abstractions.size()));
  out.key("prior");
  out.embed(nlohmann::json(catalog.prior));
  out.key("observation");
  out.embed(observation_json(catalog));
  out.key("abstractions");
  out.begin_array();
  for (const pipeline::ContinuousAbstraction& abstraction : catalog.abstractions)
    write_abstraction(out, catalog, abstraction, with_transitions);
  out.end_array();
  out.end_object();
}

std::string continuous_catalog_json(const pipeline::ContinuousCatalog& catalog,
                                    bool with_transitions) {
  return json_text(
      [&](JsonWriter& out) { write_continuous_catalog_json(out, catalog, with_transitions); });
}

}  // namespace oasis::codegen
