#include "geom/polytope_mdp.hpp"

#include <algorithm>

#include "geom/bsp_box_split.hpp"
#include "geom/polytope_error_bound.hpp"

namespace oasis::geom {
namespace {

bool inside_undisturbed_domain(const PolytopeGeometry& geometry, const AffineStep& step,
                               const Point& mean) {
  for (std::size_t i = 0; i < mean.size(); ++i) {
    if (step.disturbance[i]) continue;
    if (mean[i] < geometry.domain_low[i] || mean[i] > geometry.domain_high[i]) return false;
  }
  return true;
}

// The disturbance box around `mean`: its corners on the disturbed axes, and the mean's value on
// each undisturbed one (where the box is a slice).
struct DisturbedBox {
  std::vector<std::optional<Rational>> fixed;
  Point low;
  Point high;
};

DisturbedBox disturbed_box(const AffineStep& step, const Point& mean) {
  DisturbedBox box;
  box.fixed.resize(mean.size());
  for (std::size_t i = 0; i < mean.size(); ++i) {
    if (step.disturbance[i]) {
      box.low.push_back(mean[i] + step.disturbance[i]->low);
      box.high.push_back(mean[i] + step.disturbance[i]->high);
    } else {
      box.fixed[i] = mean[i];
    }
  }
  return box;
}

// vol(B ∩ Q) / vol(B) in the disturbed coordinates, on the slice at the mean's undisturbed
// coordinates. Only the constraints of Q that cut the box are kept, so that a box well
// inside one cell costs nothing and the vertex enumeration stays small.
Rational box_share(const Polytope& cell, const AffineStep& step, const Point& mean,
                   const Rational& box_volume) {
  const auto [fixed, low, high] = disturbed_box(step, mean);
  Polytope clipped = Polytope::box(low, high);
  const Polytope slice = cell.slice(fixed);
  for (const HalfSpace& h : slice.constraints()) {
    Rational least = 0;
    Rational most = 0;
    for (std::size_t j = 0; j < h.normal.size(); ++j) {
      least += std::min(h.normal[j] * low[j], h.normal[j] * high[j]);
      most += std::max(h.normal[j] * low[j], h.normal[j] * high[j]);
    }
    if (least >= h.bound && most > h.bound) return 0;  // the box is beyond this face
    if (most > h.bound) clipped.add(h);                // else it holds on the whole box
  }
  return clipped.volume() / box_volume;
}

// The pieces of the box B in one walk of the tree (geom/bsp_box_split.hpp) when B has one
// or two disturbed axes; nullopt otherwise. Their measures are vol(B ∩ Q) exactly, as
// box_share's, so the rows do not depend on the path taken.
std::optional<std::vector<CellMeasure>> pieces_of_box(const BspTree& tree,
                                                      std::span<const RoundedBspNode> rounded,
                                                      const AffineStep& step, const Point& mean) {
  const auto [fixed, low, high] = disturbed_box(step, mean);
  return box_cell_measures(tree, fixed, low, high, rounded);
}

}  // namespace

std::vector<std::pair<std::size_t, Rational>> successor_row(
    const PolytopeGeometry& geometry, const BspTree& tree, const AffineStep& step,
    const Point& from, std::span<const RoundedBspNode> rounded) {
  Point mean = step.offset;
  for (std::size_t i = 0; i < mean.size(); ++i)
    mean[i] += dot(step.matrix[i], from);
  std::vector<std::pair<std::size_t, Rational>> row;
  const std::size_t outside = tree.num_cells();
  if (!inside_undisturbed_domain(geometry, step, mean)) {
    row.emplace_back(outside, 1);
    return row;
  }
  Rational box_volume = 1;
  bool disturbed = false;
  for (const auto& w : step.disturbance) {
    if (!w) continue;
    box_volume *= w->width();
    disturbed = true;
  }
  if (!disturbed) {  // a point: one cell (the undisturbed check put it in the domain)
    row.emplace_back(*tree.locate(mean), 1);
    return row;
  }
  auto range = [&](const std::vector<Rational>& normal) {
    const Rational centre = dot(normal, mean);
    ValueRange r{centre, centre};
    add_disturbance(step, normal, r);
    return r;
  };
  Rational inside = 0;
  if (auto pieces = pieces_of_box(tree, rounded, step, mean)) {
    for (auto& [cell, measure] : *pieces) {
      measure /= box_volume;
      inside += measure;
      row.emplace_back(cell, std::move(measure));
    }
    if (inside < 1) row.emplace_back(outside, 1 - inside);
    return row;
  }
  for (const std::uint32_t cell : tree.cells_meeting(range)) {
    const Rational p = box_share(tree.cells()[cell].polytope, step, mean, box_volume);
    if (sgn(p) <= 0) continue;
    inside += p;
    row.emplace_back(cell, p);
  }
  if (inside < 1) row.emplace_back(outside, 1 - inside);
  return row;
}

PolytopeMdp polytope_finite_mdp(const PolytopeGeometry& geometry,
                                const PolytopePartition& partition,
                                const std::vector<std::string>& action_names,
                                const model::Objective& objective) {
  PolytopeMdp result;
  model::ExplicitModel& mdp = result.mdp;
  mdp.name = geometry.context;
  mdp.actions = action_names;
  mdp.objective = objective;
  const BspTree& tree = partition.tree;
  const auto num_states = static_cast<std::uint32_t>(tree.num_cells() + 1);
  mdp.states.size = num_states;
  const std::vector<RoundedBspNode> rounded = tree.rounded_nodes();  // for the rows' filter
  const auto num_actions = static_cast<model::ActionIndex>(action_names.size());
  model::TransitionBuilder transitions(num_states, num_actions);
  model::RewardTable rewards;
  rewards.state.assign(num_states, RationalPool::kZero);
  for (std::size_t cell = 0; cell < tree.num_cells(); ++cell) {
    rewards.state[cell] = mdp.values.intern(partition.cell_reward[cell]);
    for (model::ActionIndex a = 0; a < num_actions; ++a) {
      for (const auto& [target, p] : successor_row(geometry, tree, geometry.actions[a],
                                                   tree.cells()[cell].representative, rounded))
        transitions.add(static_cast<model::StateIndex>(cell), a,
                        static_cast<model::StateIndex>(target), mdp.values.intern(p));
    }
  }
  for (model::ActionIndex a = 0; a < num_actions; ++a)  // outside is absorbing
    transitions.add(num_states - 1, a, num_states - 1, RationalPool::kOne);
  auto matrix = std::make_shared<const model::TransitionMatrix>(transitions.finish(mdp.values));
  mdp.contexts.push_back({geometry.context, std::move(matrix), std::move(rewards)});
  result.epsilon = partition_error_bound(geometry, tree);
  return result;
}

}  // namespace oasis::geom
