#pragma once
// The finite MDP of a polytope partition (geom/polytope_mdp.hpp states it) kept as the walks
// of the tree found it (geom/polytope_rows.hpp): per cell and action, the subtrees that lie
// inside the disturbance box and the few cells its boundary cuts, with their exact
// probabilities. A subtree's cells all get vol(Q) / vol(B), so one sum per subtree, made once
// per sweep, stands for all of them: a row of a fine partition meets thousands of cells but
// holds a few hundred numbers here. Expectations are what value iteration and the proof that
// no two cells are bisimilar (bisim/discrete_proof.hpp) need; materialise() gives the exact
// rows when they are written or refined.
//
// States are numbered as in polytope_mdp.hpp: the cells in the tree's cell order, then
// `outside`, absorbing with reward 0. Every action is enabled everywhere.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "geom/bsp_subtrees.hpp"
#include "geom/polytope_geometry.hpp"
#include "geom/polytope_partition.hpp"
#include "model/explicit_model.hpp"
#include "support/rational.hpp"

namespace oasis::geom {

class PolytopeWalkRows {
 public:
  PolytopeWalkRows(const PolytopeGeometry& geometry, const PolytopePartition& partition);

  [[nodiscard]] std::uint32_t num_states() const { return num_cells_ + 1; }
  [[nodiscard]] std::uint32_t num_cells() const { return num_cells_; }
  [[nodiscard]] std::uint32_t num_actions() const { return num_actions_; }
  // Edges the materialised rows have (with `outside`'s self-loops).
  [[nodiscard]] std::size_t num_edges() const { return num_edges_; }
  // Entries this form keeps instead: subtrees and cut targets.
  [[nodiscard]] std::size_t num_entries() const { return whole_node_.size() + cut_target_.size(); }
  // R(s) exactly, interned in values(); `outside`'s is 0.
  [[nodiscard]] ValueId state_reward(std::uint32_t s) const { return reward_[s]; }
  [[nodiscard]] const RationalPool& values() const { return values_; }

  // The sums over every subtree of vol(Q) x[Q], for the expectations that follow; call it
  // again whenever x changes. Not thread-safe: one object per thread.
  void prepare(const double* x) const;
  // Σ_t P(s, a, t) x[t] over every state t (x[num_cells()] is `outside`'s), for the x last
  // given to prepare(), in doubles.
  [[nodiscard]] double expectation(std::uint32_t s, std::uint32_t a, const double* x) const;
  // A bound on the roundings along any one term's path through prepare() and expectation():
  // its relative error is at most (1 + u)^D - 1 of the exact sum when x is exact and
  // non-negative.
  [[nodiscard]] std::uint32_t rounding_depth() const { return rounding_depth_; }
  // No term of an expectation is smaller than this times its x.
  [[nodiscard]] double smallest_term() const { return smallest_term_; }

  // The exact rows as a finite MDP with one context (and these rows' values and rewards).
  [[nodiscard]] model::ExplicitModel materialise(const std::string& name,
                                                 const std::vector<std::string>& action_names,
                                                 const model::Objective& objective) const;

 private:
  struct Choice {
    std::uint32_t whole_begin = 0;  // into whole_node_
    std::uint32_t cut_begin = 0;    // into cut_*
  };
  void add_row(std::uint32_t cell, std::uint32_t a, const PolytopeGeometry& geometry,
               const PolytopePartition& partition, std::span<const RoundedBspNode> rounded);
  void finish_choice();
  [[nodiscard]] const Choice& choice(std::uint32_t s, std::uint32_t a) const {
    return choices_[std::size_t{s} * num_actions_ + a];
  }

  std::uint32_t num_cells_ = 0;
  std::uint32_t num_actions_ = 0;
  BspSubtrees subtrees_;
  std::vector<BspNode> nodes_;                   // the tree's shape, for the subtree sums
  std::vector<Rational> cell_volume_;            // exact, for materialising whole cells
  std::vector<double> near_volume_;              // the same, within one ulp
  std::vector<Rational> box_volume_;             // per action, vol(W)
  std::vector<double> near_inverse_box_volume_;  // per action, 1 / vol(W) within one ulp
  std::vector<Choice> choices_;                  // per (state, action), then one past the end
  std::vector<std::uint32_t> whole_node_;
  std::vector<std::uint32_t> cut_target_;
  std::vector<ValueId> cut_id_;
  std::vector<double> cut_probability_;  // within one ulp of the exact
  std::vector<ValueId> reward_;
  RationalPool values_;
  std::size_t num_edges_ = 0;
  std::uint32_t rounding_depth_ = 0;
  double smallest_term_ = 1;
  mutable std::vector<double> subtree_sum_;
};

}  // namespace oasis::geom
