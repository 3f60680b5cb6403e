#include "pipeline/continuous_catalog_data.hpp"

#include <cmath>

namespace oasis::pipeline {
namespace {

void add_bsp(const CellPartition& cells, model::AbstractionData& data) {
  data.bsp_cells = static_cast<std::uint32_t>(cells.num_cells());
  data.bsp_normal = cells.bsp->normal;
  data.bsp_bound = cells.bsp->bound;
  data.bsp_below = cells.bsp->below;
  data.bsp_above = cells.bsp->above;
  data.bsp_cell = cells.bsp->cell;
}

model::AbstractionData abstraction_data(const pipeline::ContinuousAbstraction& abstraction,
                                        std::uint32_t num_actions, bool with_transitions) {
  model::AbstractionData data;
  data.context = abstraction.context;
  data.num_blocks = abstraction.num_blocks;
  data.block_reward = abstraction.block_reward;
  const model::ExplicitModel& quotient = abstraction.quotient;
  if (with_transitions) data.quotient = model::csr_of(quotient, *quotient.contexts[0].transitions);
  data.reward.resize(std::size_t{data.num_blocks} * num_actions);
  for (model::StateIndex z = 0; z < data.num_blocks; ++z) {
    for (model::ActionIndex a = 0; a < num_actions; ++a)
      data.reward[std::size_t{z} * num_actions + a] = to_double(quotient.reward(0, z, a));
  }
  data.policy = abstraction.policy;
  data.value = abstraction.value;
  data.grid_axes = abstraction.axes;
  data.grid_break_begin.push_back(0);
  for (const std::vector<double>& breaks : abstraction.cells.breaks) {
    data.grid_breaks.insert(data.grid_breaks.end(), breaks.begin(), breaks.end());
    data.grid_break_begin.push_back(static_cast<std::uint32_t>(data.grid_breaks.size()));
  }
  if (abstraction.cells.bsp) add_bsp(abstraction.cells, data);
  data.cell_block = abstraction.cell_block;
  data.outside_block = abstraction.outside_block;
  data.epsilon = bound_as_double(abstraction.epsilon);
  return data;
}

}  // namespace

double bound_as_double(const Rational& bound) {
  const double nearest = to_double(bound);
  return Rational(nearest) < bound ? std::nextafter(nearest, HUGE_VAL) : nearest;
}

model::CatalogData continuous_catalog_data(const pipeline::ContinuousCatalog& catalog,
                                           bool with_transitions) {
  model::CatalogData data;
  data.name = catalog.name;
  data.spec_hash = catalog.spec_hash;
  data.compiler_version = catalog.compiler_version;
  data.num_states = 0;
  data.num_actions = static_cast<std::uint32_t>(catalog.action_names.size());
  data.action_names = catalog.action_names;
  data.switching = catalog.switching;
  data.prior = catalog.prior;
  data.variable_names = catalog.variable_names;
  data.position = catalog.position;
  data.reward_source = catalog.reward_source;
  for (const pipeline::ContinuousAbstraction& abstraction : catalog.abstractions)
    data.abstractions.push_back(abstraction_data(abstraction, data.num_actions, with_transitions));
  return data;
}

}  // namespace oasis::pipeline
