#pragma once
// The checks that make a guess a proven bound, for one side's game (docs/guarantees.md,
// "Unbounded objectives"), and policy iteration, the fastest way to a guess. Write B for the
// game's operator (best action; the disturbance's worst distribution for the lower bound, its
// best for the upper) and B_π for it under a controller π. On [0, 1]^cells all are monotone:
//
// - a pre-fixed point u (B u <= u, B rounded up) lies above B's least fixed point;
// - a post-fixed point v of B_π (v <= B_π v, B_π rounded down) lies below B_π's fixed point
//   when π has no trap (end_components.hpp), hence below B's least fixed point too.
//
// A guess near a fixed point can miss by a hair on a few cells: each check also tries the
// guess's next few images under the operator (each checked), which even that out.

#include <cstdint>
#include <optional>
#include <vector>

#include "guarantee/interval_mdp.hpp"
#include "guarantee/objective_cells.hpp"
#include "guarantee/robust_value.hpp"
#include "guarantee/sweeper.hpp"

namespace oasis::guarantee {

class Certificates {
 public:
  Certificates(const IntervalMdp& mdp, const ObjectiveCells& cells, SweepMode mode, Bound bound);

  // 1 for the cells whose value in this game is not fixed.
  [[nodiscard]] const std::vector<std::uint8_t>& undecided() const { return undecided_; }
  // Each cell's fixed value, and 0 where it must be solved.
  [[nodiscard]] std::vector<double> fixed_or_zero() const;

  // Whether `candidate`, or one of its next images under B_π, is a post-fixed point of B_π
  // rounded down; on success `candidate` holds it.
  bool post_fixed(std::vector<double>& candidate, const std::vector<std::uint32_t>& policy);
  // Whether `guess`, or one of its next images under B, is a pre-fixed point of B rounded up;
  // on success `guess` holds it.
  bool pre_fixed(std::vector<double>& guess);
  // Whether `policy` has no trap, so that B_π has a single fixed point.
  [[nodiscard]] bool trap_free(const std::vector<std::uint32_t>& policy) const;

  // Policy iteration from `values`: the controller greedy at the current values (a cell
  // switches only on a gain above 1e-12), the distributions the disturbance picks, and the
  // chain they make solved as a linear system; until the controller stays or the values
  // settle. A guess, or nothing when a solve fails or when three solves in a row each move
  // some value by half or more (nearly deterministic rows: a round per step of the way). `rounds`
  // counts the solves.
  std::optional<std::vector<double>> policy_iteration(std::vector<double> values,
                                                      std::vector<std::uint32_t>& policy,
                                                      std::uint64_t& rounds);

 private:
  // Whether `guess`, or one of its next few images (`image(cell, table)` on the undecided
  // cells), has holds(image, value) on every undecided cell; on success `guess` holds it.
  template <typename Image, typename Holds>
  bool settles(std::vector<double>& guess, const Image& image, const Holds& holds);

  // `values` in the one table that policy iteration and every check read, whose drift then
  // bounds how far values have moved since `sweeper_` cached an action's value: the
  // improvement and the pre-fixed check skip the actions that cannot win (Sweeper::update),
  // also right after policy iteration, whose last guess is near what the check reads.
  const ValueTable& table_for(const std::vector<double>& values);

  const IntervalMdp& mdp_;
  Bound bound_;
  Sweeper sweeper_;  // its action cache belongs to table_
  std::vector<std::uint8_t> undecided_;
  std::optional<ValueTable> table_;
  std::vector<std::uint32_t> favourite_;  // per cell, the action tried first
};

// `values` plus `lift` on the undecided cells, within [0, 1].
std::vector<double> shifted(std::vector<double> values, double lift,
                            const std::vector<std::uint8_t>& undecided);

// The largest above[c] - below[c].
double largest_difference(const std::vector<double>& above, const std::vector<double>& below);

}  // namespace oasis::guarantee
