#pragma once
// One cell's update in the sweeps of controller synthesis (docs/guarantees.md): the fixed
// values of decided cells, the robust values of a cell's actions, and the best of them.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "guarantee/interval_mdp.hpp"
#include "guarantee/objective_cells.hpp"
#include "guarantee/robust_value.hpp"

namespace oasis::guarantee {

enum class Bound { Lower, Upper };
enum class Rounding { Down, Up };

// How each game rounds in its chooser's favour: the lower game's chooser (the disturbance,
// minimising) down, the upper game's up.
inline Rounding chooser_rounding(Bound bound) {
  return bound == Bound::Lower ? Rounding::Down : Rounding::Up;
}

// The objective as the sweeps read it.
enum class SweepMode { Safety, Reach, ReachAt };

SweepMode sweep_mode(const model::GuaranteeObjective& objective);

class Sweeper {
 public:
  Sweeper(const IntervalMdp& mdp, const ObjectiveCells& cells, SweepMode mode)
      : mdp_(mdp), cells_(cells), mode_(mode) {}

  // The value of a cell with no step left.
  [[nodiscard]] double terminal(std::size_t cell, Bound bound) const;
  // The value a cell has whatever happens next, or a negative number when it must be solved.
  [[nodiscard]] double fixed(std::size_t cell, Bound bound) const;
  // Each cell's fixed value, and 0 where it must be solved: where iterations from below start.
  [[nodiscard]] std::vector<double> fixed_or_zero(Bound bound) const;
  [[nodiscard]] RobustGame game(Bound bound) const;

  // The first action of greatest value at `cell` under `values`, and that value, rounded in the
  // chooser's favour.
  double best_action(std::size_t cell, const ValueTable& values, Bound bound,
                     std::uint32_t& action);

  struct Choice {
    double best;    // the greatest value over the actions
    double chosen;  // the value of `action` after the update
  };

  // The iterations' update: the greatest value over the actions at `cell`, trying `action`
  // first; `action` becomes the best one only if it gains more than `switch_gain` over it (the
  // lower bound's controller keeps its action unless another is really better).
  //
  // Actions are skipped when they cannot win: a robust value moves by at most as much as the
  // values it reads (it is 1-Lipschitz in the largest change), so an action whose value, when
  // last computed, was below the best by more than everything has moved since, still is.
  // ValueTable::drift() bounds that movement. This skips most actions once the values settle.
  // The cache belongs to one table: a Sweeper's update() always reads the same ValueTable.
  Choice update(std::size_t cell, const ValueTable& values, Bound bound, std::uint32_t& action,
                double switch_gain) {
    return update(cell, values, bound, action, switch_gain, chooser_rounding(bound));
  }
  // The same, every value rounded the way asked (a check that values lie above B's least fixed
  // point rounds the lower game's values up).
  Choice update(std::size_t cell, const ValueTable& values, Bound bound, std::uint32_t& action,
                double switch_gain, Rounding rounding);

  // The robust value of `action` at `cell` in `bound`'s game (its fixed value if it has one),
  // rounded the way asked: each game rounds in its chooser's favour, and a check that values
  // lie on the other side of a fixed point rounds the other way.
  double action_value(std::size_t cell, const ValueTable& values, std::uint32_t action, Bound bound,
                      Rounding rounding);

  // The lower bound's robust value of `action` at `cell`, rounded down.
  double evaluate(std::size_t cell, const ValueTable& values, std::uint32_t action) {
    return action_value(cell, values, action, Bound::Lower, Rounding::Down);
  }

 private:
  [[nodiscard]] bool safe(std::size_t cell, Bound bound) const {
    return (bound == Bound::Lower ? cells_.safe_lower : cells_.safe_upper)[cell] != 0;
  }
  [[nodiscard]] bool target(std::size_t cell, Bound bound) const {
    return (bound == Bound::Lower ? cells_.target_lower : cells_.target_upper)[cell] != 0;
  }

  const IntervalMdp& mdp_;
  const ObjectiveCells& cells_;
  SweepMode mode_;
  RobustScratch scratch_;
  // Per (cell, action): its value when last computed, rounded up, and the drift base of that
  // sweep, rounded down, so that a skip stays safe. Floats: on the vehicle's 4.4 M pairs,
  // each of the four caches (a sweeper and a checker per bound) holds 35 MB instead of 70.
  std::vector<float> cached_value_;
  std::vector<float> cached_drift_;
};

}  // namespace oasis::guarantee
