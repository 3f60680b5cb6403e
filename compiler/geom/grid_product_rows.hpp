#pragma once
// The finite MDP of a gridded context (geom/grid_mdp.hpp states it) kept in product form: per
// cell, action and axis the axis row of grid_axis_rows.hpp, its probabilities rounded to the
// nearest doubles, and the mass that leaves the domain. A row of the finite MDP has Π_i n_i
// targets; here it takes Σ_i n_i numbers, so the rows of a fine grid fit where the
// materialised MDP would not (the Go1 at ε 0.05: 82 M edges per context). Expectations are
// taken axis by axis, as nested sums: what value iteration and the proof that no two cells are
// bisimilar (bisim/discrete_proof.hpp) need, and all they need.
//
// States are numbered as in grid_mdp.hpp: the cells in the grid's row-major order, then
// `outside`, absorbing with reward 0. Every action is enabled everywhere.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "geom/grid.hpp"
#include "geom/grid_axis_rows.hpp"
#include "geom/grid_geometry.hpp"
#include "support/rational.hpp"

namespace oasis::geom {

class ProductRows {
 public:
  // One axis of one (cell, action): the intervals first .. first + count - 1, whose
  // probabilities start at probability()[offset].
  struct AxisSpan {
    std::uint32_t first = 0;
    std::uint32_t count = 0;
    std::uint64_t offset = 0;
  };

  ProductRows(const GridGeometry& geometry, const Grid& grid, std::uint32_t num_actions);

  [[nodiscard]] std::uint32_t num_states() const { return num_cells_ + 1; }
  [[nodiscard]] std::uint32_t num_cells() const { return num_cells_; }
  [[nodiscard]] std::uint32_t num_actions() const { return num_actions_; }
  [[nodiscard]] std::size_t dimension() const { return extent_.size(); }
  // Edges the materialised rows would have (with `outside`'s self-loops).
  [[nodiscard]] std::size_t num_edges() const { return num_edges_; }
  // Numbers this form keeps instead: the axis rows' probabilities.
  [[nodiscard]] std::size_t num_numbers() const { return probability_.size(); }
  // R(s) exactly, interned in values(); `outside`'s is 0.
  [[nodiscard]] ValueId state_reward(std::uint32_t s) const { return reward_[s]; }
  [[nodiscard]] const RationalPool& values() const { return values_; }
  // The exact rows, for materialising them (grid_mdp.hpp): the span of one axis of a cell's
  // row under action a, the exact probability of a span's k-th interval, and the mass that
  // leaves the domain.
  [[nodiscard]] const AxisSpan& span(std::uint32_t cell, std::uint32_t a, std::size_t axis) const {
    return spans_[(std::size_t{cell} * num_actions_ + a) * extent_.size() + axis];
  }
  [[nodiscard]] ValueId probability_id(const AxisSpan& span, std::uint32_t k) const {
    return probability_id_[span.offset + k];
  }
  [[nodiscard]] ValueId outside_id(std::uint32_t cell, std::uint32_t a) const {
    return outside_id_[std::size_t{cell} * num_actions_ + a];
  }
  [[nodiscard]] const std::vector<std::uint32_t>& extent() const { return extent_; }

  // Σ_t P(s, a, t) x[t] over every state t (x[num_cells()] is `outside`'s), summed axis by
  // axis with the probabilities rounded to the nearest doubles.
  [[nodiscard]] double expectation(std::uint32_t s, std::uint32_t a, const double* x) const;
  // A bound on the roundings along any one term's path through expectation(): its relative
  // error is at most (1 + u)^D - 1 of the exact sum when every x is exact and non-negative.
  [[nodiscard]] std::uint32_t rounding_depth() const { return rounding_depth_; }
  // The least product of one probability per axis (or of the outside mass): no term of an
  // expectation is smaller than this times its x.
  [[nodiscard]] double smallest_term() const { return smallest_term_; }

 private:
  // Appends an axis row's probabilities; its span.
  AxisSpan add_axis_row(const AxisRow& row);
  // Counts the edges of one (cell, action) and the roundings of its expectation.
  void count_choice(std::size_t choice);
  // The probabilities in doubles, and the least term.
  void round_numbers();
  [[nodiscard]] double axis_sum(const AxisSpan* spans, std::size_t axis, std::size_t prefix,
                                const double* x) const;

  std::vector<std::uint32_t> extent_;  // intervals per axis
  std::uint32_t num_cells_ = 0;
  std::uint32_t num_actions_ = 0;
  std::vector<AxisSpan> spans_;          // [(cell * actions + a) * dimension + axis]
  std::vector<ValueId> probability_id_;  // the spans' probabilities, exactly
  std::vector<double> probability_;      // and rounded to the nearest doubles
  std::vector<ValueId> outside_id_;      // [cell * actions + a]: the mass that leaves the domain
  std::vector<double> outside_;
  std::vector<ValueId> reward_;  // [state]
  RationalPool values_;
  std::size_t num_edges_ = 0;
  std::uint32_t rounding_depth_ = 0;
  double smallest_term_ = 1;
};

}  // namespace oasis::geom
