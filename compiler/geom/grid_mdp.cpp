#include "geom/grid_mdp.hpp"

#include <algorithm>
#include <memory>
#include <unordered_map>

namespace oasis::geom {
namespace {

// p * q, interned once per pair of ids: few distinct values recur across the grid.
class ProductPool {
 public:
  explicit ProductPool(RationalPool& values) : values_(values) {}

  ValueId product(ValueId p, ValueId q) {
    if (p == RationalPool::kOne) return q;
    if (q == RationalPool::kOne) return p;
    const std::uint64_t key = (std::uint64_t{std::min(p, q)} << 32) | std::max(p, q);
    const auto [slot, inserted] = products_.try_emplace(key, 0);
    if (inserted) slot->second = values_.intern(values_[p] * values_[q]);
    return slot->second;
  }

 private:
  RationalPool& values_;
  std::unordered_map<std::uint64_t, ValueId> products_;
};

// Adds the row of one cell under one action: the product of its axis rows (an odometer over
// them, the last axis fastest, so targets come in increasing order), and the rest of the mass
// to `outside`.
void add_cell_row(const ProductRows& rows, std::uint32_t cell, model::ActionIndex action,
                  ProductPool& products, model::TransitionBuilder& transitions) {
  const std::size_t d = rows.dimension();
  const std::vector<std::uint32_t>& extent = rows.extent();
  std::vector<const ProductRows::AxisSpan*> spans(d);
  for (std::size_t i = 0; i < d; ++i)
    spans[i] = &rows.span(cell, action, i);
  if (spans[0]->count > 0) {
    std::vector<std::uint32_t> position(d, 0);
    for (;;) {
      ValueId p = RationalPool::kOne;
      std::size_t target = 0;
      for (std::size_t i = 0; i < d; ++i) {
        target = target * extent[i] + spans[i]->first + position[i];
        p = products.product(p, rows.probability_id(*spans[i], position[i]));
      }
      transitions.add(cell, action, static_cast<model::StateIndex>(target), p);
      std::size_t i = d;
      while (i > 0 && ++position[i - 1] == spans[i - 1]->count)
        position[--i] = 0;
      if (i == 0) break;
    }
  }
  const ValueId leaving = rows.outside_id(cell, action);
  if (leaving != RationalPool::kZero) transitions.add(cell, action, rows.num_cells(), leaving);
}

}  // namespace

model::ExplicitModel grid_finite_mdp(const ProductRows& rows, const std::string& context,
                                     const std::vector<std::string>& action_names,
                                     const model::Objective& objective) {
  model::ExplicitModel mdp;
  mdp.name = context;
  mdp.actions = action_names;
  mdp.objective = objective;
  mdp.values = rows.values();
  const std::uint32_t num_states = rows.num_states();
  mdp.states.size = num_states;
  const auto num_actions = static_cast<model::ActionIndex>(action_names.size());
  model::TransitionBuilder transitions(num_states, num_actions);
  transitions.reserve(rows.num_edges());
  model::RewardTable rewards;
  rewards.state.resize(num_states);
  ProductPool products(mdp.values);
  for (std::uint32_t cell = 0; cell < rows.num_cells(); ++cell) {
    rewards.state[cell] = rows.state_reward(cell);
    for (model::ActionIndex a = 0; a < num_actions; ++a)
      add_cell_row(rows, cell, a, products, transitions);
  }
  rewards.state[num_states - 1] = RationalPool::kZero;
  for (model::ActionIndex a = 0; a < num_actions; ++a)  // outside is absorbing
    transitions.add(num_states - 1, a, num_states - 1, RationalPool::kOne);

  auto matrix = std::make_shared<const model::TransitionMatrix>(transitions.finish(mdp.values));
  mdp.contexts.push_back({context, std::move(matrix), std::move(rewards)});
  return mdp;
}

model::ExplicitModel grid_finite_mdp(const GridGeometry& geometry, const Grid& grid,
                                     const std::vector<std::string>& action_names,
                                     const model::Objective& objective) {
  const ProductRows rows(geometry, grid, static_cast<std::uint32_t>(action_names.size()));
  return grid_finite_mdp(rows, geometry.context, action_names, objective);
}

}  // namespace oasis::geom
