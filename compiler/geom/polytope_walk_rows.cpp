#include "geom/polytope_walk_rows.hpp"

#include <algorithm>
#include <memory>

#include "geom/polytope_rows.hpp"

namespace oasis::geom {
namespace {

// Roundings charged to a number converted with get_d(): it truncates, so it is within one ulp
// (two unit roundoffs) of the exact value rather than half of one.
constexpr std::uint32_t kTruncation = 2;

// The longest path from the root to a leaf, in nodes below the root.
std::uint32_t tree_height(const std::vector<BspNode>& nodes) {
  std::vector<std::uint32_t> depth(nodes.size(), 0);
  std::uint32_t height = 0;
  for (std::uint32_t n = 0; n < nodes.size(); ++n) {  // a parent comes before its children
    if (nodes[n].is_leaf()) {
      height = std::max(height, depth[n]);
      continue;
    }
    depth[nodes[n].below] = depth[n] + 1;
    depth[nodes[n].above] = depth[n] + 1;
  }
  return height;
}

}  // namespace

PolytopeWalkRows::PolytopeWalkRows(const PolytopeGeometry& geometry,
                                   const PolytopePartition& partition)
    : num_cells_(static_cast<std::uint32_t>(partition.tree.num_cells())),
      num_actions_(static_cast<std::uint32_t>(geometry.actions.size())),
      subtrees_(partition.tree),
      nodes_(partition.tree.nodes()) {
  const BspTree& tree = partition.tree;
  for (const BspCell& cell : tree.cells()) {
    cell_volume_.push_back(cell.volume);
    near_volume_.push_back(cell.volume.get_d());
  }
  for (const AffineStep& step : geometry.actions) {
    box_volume_.push_back(box_volume_of(step));
    near_inverse_box_volume_.push_back(Rational(1 / box_volume_.back()).get_d());
  }
  reward_.assign(num_states(), RationalPool::kZero);
  const std::vector<RoundedBspNode> rounded = tree.rounded_nodes();  // for the walk's filter
  for (std::uint32_t cell = 0; cell < num_cells_; ++cell) {
    reward_[cell] = values_.intern(partition.cell_reward[cell]);
    for (std::uint32_t a = 0; a < num_actions_; ++a)
      add_row(cell, a, geometry, partition, rounded);
  }
  for (std::uint32_t a = 0; a < num_actions_; ++a) {  // outside is absorbing
    choices_.push_back({static_cast<std::uint32_t>(whole_node_.size()),
                        static_cast<std::uint32_t>(cut_target_.size())});
    cut_target_.push_back(num_cells_);
    cut_id_.push_back(RationalPool::kOne);
    cut_probability_.push_back(1);
    ++num_edges_;
  }
  choices_.push_back({static_cast<std::uint32_t>(whole_node_.size()),
                      static_cast<std::uint32_t>(cut_target_.size())});
  // A whole cell's term: its volume (truncated), the product with x, the subtree sums up to
  // the row's subtree, the row's sums and 1 / vol(W) (truncated) and its product. A cut
  // term: its probability (truncated), the product and the row's sums.
  const std::uint32_t height = tree_height(nodes_);
  for (std::size_t c = 0; c + 1 < choices_.size(); ++c) {
    const std::uint32_t entries = (choices_[c + 1].whole_begin - choices_[c].whole_begin) +
                                  (choices_[c + 1].cut_begin - choices_[c].cut_begin);
    rounding_depth_ = std::max(rounding_depth_, 2 * kTruncation + 2 + height + entries);
  }
  for (std::uint32_t a = 0; a < num_actions_; ++a)
    for (const double v : near_volume_)
      smallest_term_ = std::min(smallest_term_, v * near_inverse_box_volume_[a] / 2);
  for (const double p : cut_probability_)
    smallest_term_ = std::min(smallest_term_, p / 2);
  subtree_sum_.resize(nodes_.size());
}

void PolytopeWalkRows::add_row(std::uint32_t cell, std::uint32_t a,
                               const PolytopeGeometry& geometry, const PolytopePartition& partition,
                               std::span<const RoundedBspNode> rounded) {
  choices_.push_back({static_cast<std::uint32_t>(whole_node_.size()),
                      static_cast<std::uint32_t>(cut_target_.size())});
  const BspTree& tree = partition.tree;
  const RowParts row = successor_parts(geometry, tree, geometry.actions[a],
                                       tree.cells()[cell].representative, rounded, &subtrees_);
  for (const std::uint32_t node : row.whole_subtrees) {
    whole_node_.push_back(node);
    num_edges_ += subtrees_.cells(node).size();
  }
  for (const auto& [target, p] : row.shares) {
    cut_target_.push_back(static_cast<std::uint32_t>(target));
    cut_id_.push_back(values_.intern(p));
    cut_probability_.push_back(p.get_d());
  }
  num_edges_ += row.shares.size();
}

void PolytopeWalkRows::prepare(const double* x) const {
  for (std::size_t n = nodes_.size(); n-- > 0;) {  // children come after their parent
    const BspNode& node = nodes_[n];
    subtree_sum_[n] = node.is_leaf() ? near_volume_[node.cell] * x[node.cell]
                                     : subtree_sum_[node.below] + subtree_sum_[node.above];
  }
}

double PolytopeWalkRows::expectation(std::uint32_t s, std::uint32_t a, const double* x) const {
  const std::size_t c = std::size_t{s} * num_actions_ + a;
  double whole = 0;
  for (std::uint32_t k = choices_[c].whole_begin; k < choices_[c + 1].whole_begin; ++k)
    whole += subtree_sum_[whole_node_[k]];
  double total = whole * near_inverse_box_volume_[a];
  for (std::uint32_t k = choices_[c].cut_begin; k < choices_[c + 1].cut_begin; ++k)
    total += cut_probability_[k] * x[cut_target_[k]];
  return total;
}

model::ExplicitModel PolytopeWalkRows::materialise(const std::string& name,
                                                   const std::vector<std::string>& action_names,
                                                   const model::Objective& objective) const {
  model::ExplicitModel mdp;
  mdp.name = name;
  mdp.actions = action_names;
  mdp.objective = objective;
  mdp.states.size = num_states();
  mdp.values = values_;
  // vol(Q) / vol(W) per action and cell, interned when first met.
  constexpr ValueId kUnknown = UINT32_MAX;
  std::vector<std::vector<ValueId>> whole_id(num_actions_,
                                             std::vector<ValueId>(num_cells_, kUnknown));
  model::TransitionBuilder transitions(num_states(), num_actions_);
  transitions.reserve(num_edges_);
  for (std::uint32_t s = 0; s < num_states(); ++s) {
    for (std::uint32_t a = 0; a < num_actions_; ++a) {
      const std::size_t c = std::size_t{s} * num_actions_ + a;
      for (std::uint32_t k = choices_[c].whole_begin; k < choices_[c + 1].whole_begin; ++k) {
        for (const std::uint32_t target : subtrees_.cells(whole_node_[k])) {
          ValueId& id = whole_id[a][target];
          if (id == kUnknown) id = mdp.values.intern(cell_volume_[target] / box_volume_[a]);
          transitions.add(s, a, target, id);
        }
      }
      for (std::uint32_t k = choices_[c].cut_begin; k < choices_[c + 1].cut_begin; ++k)
        transitions.add(s, a, cut_target_[k], cut_id_[k]);
    }
  }
  model::RewardTable rewards;
  rewards.state = reward_;
  auto matrix = std::make_shared<const model::TransitionMatrix>(transitions.finish(mdp.values));
  mdp.contexts.push_back({name, std::move(matrix), std::move(rewards)});
  return mdp;
}

}  // namespace oasis::geom
