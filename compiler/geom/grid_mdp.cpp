#include "geom/grid_mdp.hpp"

#include <algorithm>
#include <unordered_map>

#include "geom/grid_gaussian_axis.hpp"

namespace oasis::geom {
namespace {

// The probabilities of one axis: (interval index, probability id) inside the domain, and the
// exact mass that stays inside.
struct AxisRow {
  std::vector<std::pair<std::uint32_t, ValueId>> entries;
  Rational inside;
};

class RowBuilder {
 public:
  RowBuilder(const Grid& grid, RationalPool& values) : grid_(grid), values_(values) {}

  // The successor distribution of axis i from a cell with centre `centre` under `action`.
  void axis_row(const AxisDynamics& action, std::size_t i, const std::vector<Rational>& centre,
                AxisRow& row) const {
    row.entries.clear();
    // The image of the centre without its disturbance.
    Rational image = action.offset[i];
    for (std::size_t j = 0; j < centre.size(); ++j)
      if (sgn(action.matrix[i][j]) != 0) image += action.matrix[i][j] * centre[j];
    const Disturbance& w = action.disturbance[i];
    switch (w.kind) {
      case Disturbance::Kind::None:
        point_row(i, image, row);
        return;
      case Disturbance::Kind::Uniform:
        uniform_row(i, image, w.uniform, row);
        return;
      case Disturbance::Kind::Gaussian:
        gaussian_row(i, image, w.gaussian, row);
        return;
    }
  }

  // p * q, interned once per pair of ids: few distinct values recur across the grid.
  ValueId product(ValueId p, ValueId q) {
    if (p == RationalPool::kOne) return q;
    if (q == RationalPool::kOne) return p;
    const std::uint64_t key = (std::uint64_t{std::min(p, q)} << 32) | std::max(p, q);
    const auto [slot, inserted] = products_.try_emplace(key, 0);
    if (inserted) slot->second = values_.intern(values_[p] * values_[q]);
    return slot->second;
  }

 private:
  // A point: one interval, or outside.
  void point_row(std::size_t i, const Rational& point, AxisRow& row) const {
    const auto k = grid_.locate(i, point);
    row.inside = k ? 1 : 0;
    if (k) row.entries.emplace_back(*k, RationalPool::kOne);
  }

  // Uniform on image + [low, high]: each interval's share of the overlap, exactly.
  void uniform_row(std::size_t i, const Rational& image, const Interval& w, AxisRow& row) const {
    const Rational low = image + w.low;
    const Rational high = image + w.high;
    const Rational width = w.high - w.low;
    const std::vector<Rational>& t = grid_.breaks(i);
    row.inside = 0;
    // The first interval whose upper end is above `low`.
    auto k = static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), low) - t.begin());
    k = k == 0 ? 0 : k - 1;
    for (; k + 1 < t.size() && t[k] < high; ++k) {
      const Rational overlap = std::min(high, t[k + 1]) - std::max(low, t[k]);
      if (sgn(overlap) <= 0) continue;
      const Rational p = overlap / width;
      row.inside += p;
      row.entries.emplace_back(static_cast<std::uint32_t>(k), values_.intern(p));
    }
  }

  // Normal(image + w.mean, w.deviation²): the intervals under its truncated support, to the
  // tolerance of geom/grid_gaussian_axis.hpp, which the context's epsilon includes.
  void gaussian_row(std::size_t i, const Rational& image, const Gaussian& w, AxisRow& row) const {
    row.inside = 0;
    const Rational mean = image + w.mean;
    for (auto& [k, p] : gaussian_interval_probabilities(mean, w.deviation, grid_.breaks(i))) {
      row.inside += p;
      row.entries.emplace_back(k, values_.intern(p));
    }
  }

  const Grid& grid_;
  RationalPool& values_;
  std::unordered_map<std::uint64_t, ValueId> products_;
};

std::vector<Rational> centre_of(const Grid& grid, const std::vector<std::uint32_t>& index) {
  std::vector<Rational> centre(index.size());
  for (std::size_t i = 0; i < index.size(); ++i) {
    const std::vector<Rational>& t = grid.breaks(i);
    centre[i] = (t[index[i]] + t[index[i] + 1]) / 2;
  }
  return centre;
}

// Σ of the rewards whose box holds the cell (boxes are unions of cells by construction).
Rational cell_reward(const GridGeometry& geometry, const Grid& grid,
                     const std::vector<std::uint32_t>& index) {
  Rational total = 0;
  for (const RewardBox& reward : geometry.rewards) {
    bool inside = true;
    for (std::size_t i = 0; i < index.size() && inside; ++i) {
      const std::vector<Rational>& t = grid.breaks(i);
      inside = reward.box[i].low <= t[index[i]] && t[index[i] + 1] <= reward.box[i].high;
    }
    if (inside) total += reward.value;
  }
  return total;
}

// Adds the row of one cell under one action: the product of its axis rows, and the rest of
// the mass to `outside`.
void add_cell_row(const Grid& grid, std::size_t cell, model::ActionIndex action,
                  const std::vector<AxisRow>& axes, RowBuilder& rows,
                  model::TransitionBuilder& transitions, RationalPool& values) {
  const std::size_t d = axes.size();
  Rational inside = 1;
  for (const AxisRow& axis : axes)
    inside *= axis.inside;
  const auto outside = static_cast<model::StateIndex>(grid.num_cells());
  if (sgn(inside) > 0) {
    std::vector<std::size_t> position(d, 0);  // an odometer over the axis rows
    std::vector<std::uint32_t> index(d);
    for (;;) {
      ValueId p = RationalPool::kOne;
      for (std::size_t i = 0; i < d; ++i) {
        index[i] = axes[i].entries[position[i]].first;
        p = rows.product(p, axes[i].entries[position[i]].second);
      }
      transitions.add(static_cast<model::StateIndex>(cell), action,
                      static_cast<model::StateIndex>(grid.cell_of(index)), p);
      std::size_t i = d;
      while (i > 0 && ++position[i - 1] == axes[i - 1].entries.size())
        position[--i] = 0;
      if (i == 0) break;
    }
  }
  if (inside < 1) {
    transitions.add(static_cast<model::StateIndex>(cell), action, outside,
                    values.intern(1 - inside));
  }
}

}  // namespace

model::ExplicitModel grid_finite_mdp(const GridGeometry& geometry, const Grid& grid,
                                     const std::vector<std::string>& action_names,
                                     const model::Objective& objective) {
  model::ExplicitModel mdp;
  mdp.name = geometry.context;
  mdp.actions = action_names;
  mdp.objective = objective;
  const auto num_states = static_cast<std::uint32_t>(grid.num_cells() + 1);
  mdp.states.size = num_states;
  const auto num_actions = static_cast<model::ActionIndex>(action_names.size());
  model::TransitionBuilder transitions(num_states, num_actions);
  model::RewardTable rewards;
  rewards.state.assign(num_states, RationalPool::kZero);

  RowBuilder rows(grid, mdp.values);
  std::vector<std::uint32_t> index(grid.dimension());
  std::vector<AxisRow> axes(grid.dimension());
  for (std::size_t cell = 0; cell < grid.num_cells(); ++cell) {
    grid.index_of(cell, index);
    const std::vector<Rational> centre = centre_of(grid, index);
    rewards.state[cell] = mdp.values.intern(cell_reward(geometry, grid, index));
    for (model::ActionIndex a = 0; a < num_actions; ++a) {
      for (std::size_t i = 0; i < grid.dimension(); ++i)
        rows.axis_row(geometry.actions[a], i, centre, axes[i]);
      add_cell_row(grid, cell, a, axes, rows, transitions, mdp.values);
    }
  }
  for (model::ActionIndex a = 0; a < num_actions; ++a)  // outside is absorbing
    transitions.add(num_states - 1, a, num_states - 1, RationalPool::kOne);

  auto matrix = std::make_shared<const model::TransitionMatrix>(transitions.finish(mdp.values));
  mdp.contexts.push_back({geometry.context, std::move(matrix), std::move(rewards)});
  return mdp;
}

}  // namespace oasis::geom
