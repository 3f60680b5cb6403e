#include "guarantee/synthesis.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "guarantee/robust_value.hpp"

namespace oasis::guarantee {
namespace {

using Kind = model::GuaranteeObjective::Kind;

enum class Bound { Lower, Upper };

// The objective as the sweeps read it.
enum class Mode { Safety, Reach, ReachAt };

Mode mode_of(const model::GuaranteeObjective& objective) {
  if (objective.kind == Kind::Safety) return Mode::Safety;
  return objective.exactly_at_step ? Mode::ReachAt : Mode::Reach;
}

// A better lower-bound action must gain more than this before the controller switches to it:
// rounding noise must not make it move between actions of equal value, and a switch only on
// a real gain is what makes the controller attain the bound (docs/guarantees.md).
constexpr double kSwitchGain = 1e-12;

class Sweeper {
 public:
  Sweeper(const IntervalMdp& mdp, const ObjectiveCells& cells, Mode mode)
      : mdp_(mdp), cells_(cells), mode_(mode) {}

  // The value of a cell with no step left.
  [[nodiscard]] double terminal(std::size_t cell, Bound bound) const {
    if (mode_ == Mode::Safety) return safe(cell, bound) ? 1 : 0;
    return target(cell, bound) ? 1 : 0;
  }

  // The value a cell has whatever happens next, or a negative number when it must be solved.
  [[nodiscard]] double fixed(std::size_t cell, Bound bound) const {
    if (mode_ == Mode::Reach && target(cell, bound)) return 1;
    if (!safe(cell, bound)) return 0;
    return -1;
  }

  [[nodiscard]] RobustGame game(Bound bound) const {
    if (bound == Bound::Lower) return RobustGame{false, 0, 0};
    return RobustGame{true, cells_.outside_may_succeed ? 1.0 : 0.0, 1};
  }

  // The first action of greatest value at `cell` under `values`, and that value.
  double best_action(std::size_t cell, const ValueTable& values, Bound bound,
                     std::uint32_t& action) {
    const double constant = fixed(cell, bound);
    if (constant >= 0) return constant;
    const RobustGame g = game(bound);
    double best = -1;
    for (std::size_t a = 0; a < mdp_.actions.size(); ++a) {
      const double q = robust_value(mdp_, mdp_.row(cell, a), values, g, scratch_);
      if (q > best) {
        best = q;
        action = static_cast<std::uint32_t>(a);
      }
    }
    return best;
  }

  // The lower bound's update with the switching rule: keep `action` unless another gains more
  // than kSwitchGain.
  double improve(std::size_t cell, const ValueTable& values, std::uint32_t& action) {
    const double constant = fixed(cell, Bound::Lower);
    if (constant >= 0) return constant;
    const RobustGame g = game(Bound::Lower);
    double current = -1;
    double best = -1;
    std::uint32_t best_index = action;
    for (std::size_t a = 0; a < mdp_.actions.size(); ++a) {
      const double q = robust_value(mdp_, mdp_.row(cell, a), values, g, scratch_);
      if (a == action) current = q;
      if (q > best) {
        best = q;
        best_index = static_cast<std::uint32_t>(a);
      }
    }
    if (best > current + kSwitchGain) action = best_index;
    return best;
  }

  double evaluate(std::size_t cell, const ValueTable& values, std::uint32_t action) {
    const double constant = fixed(cell, Bound::Lower);
    if (constant >= 0) return constant;
    return robust_value(mdp_, mdp_.row(cell, action), values, game(Bound::Lower), scratch_);
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
  Mode mode_;
  RobustScratch scratch_;
};

double largest_gap(const std::vector<double>& lower, const std::vector<double>& upper) {
  double gap = 0;
  for (std::size_t c = 0; c < lower.size(); ++c) {
    if (lower[c] > upper[c]) {
      // Both are proven bounds on the same quantity: crossing means a bug, not a result.
      throw std::logic_error("internal error: lower bound above upper bound at cell " +
                             std::to_string(c));
    }
    gap = std::max(gap, upper[c] - lower[c]);
  }
  return gap;
}

// Backward induction over N steps: values with k steps to go from those with k - 1.
Synthesis bounded(Sweeper& sweeper, const IntervalMdp& mdp, std::uint64_t steps,
                  const SynthesisOptions& options) {
  const std::size_t cells = mdp.grid.cells;
  Synthesis result;
  std::vector<double> next_lower(cells);
  std::vector<double> next_upper(cells);
  for (std::size_t c = 0; c < cells; ++c) {
    next_lower[c] = sweeper.terminal(c, Bound::Lower);
    next_upper[c] = sweeper.terminal(c, Bound::Upper);
  }
  ValueTable lower(mdp.grid, next_lower);
  ValueTable upper(mdp.grid, next_upper);
  result.controller.assign(steps, std::vector<std::uint32_t>(cells, 0));
  for (std::uint64_t k = 1; k <= steps; ++k) {
    std::vector<std::uint32_t>& actions = result.controller[steps - k];
    for (std::size_t c = 0; c < cells; ++c) {
      next_lower[c] = sweeper.best_action(c, lower, Bound::Lower, actions[c]);
      std::uint32_t ignored = 0;
      next_upper[c] = sweeper.best_action(c, upper, Bound::Upper, ignored);
    }
    lower.set_all(next_lower);
    upper.set_all(next_upper);
    result.sweeps = k;
    if (options.progress) options.progress(k, largest_gap(lower.values(), upper.values()));
  }
  result.largest_gap = largest_gap(lower.values(), upper.values());
  result.lower = lower.release();
  result.upper = upper.release();
  result.stop_reason = "exact horizon of " + std::to_string(steps) + " steps";
  return result;
}

// Interval iteration: the lower bound from below and the upper bound from above, line by line
// (block Gauss-Seidel: a line's new values are computed from the values before it, then
// stored). Every iterate of either is a proven bound (docs/guarantees.md), so any stop is
// sound; the stop rule only decides how tight they are.
Synthesis unbounded(Sweeper& sweeper, const IntervalMdp& mdp, const SynthesisOptions& options) {
  const std::size_t cells = mdp.grid.cells;
  Synthesis result;
  std::vector<double> initial_lower(cells);
  std::vector<double> initial_upper(cells);
  for (std::size_t c = 0; c < cells; ++c) {
    const double lower_fixed = sweeper.fixed(c, Bound::Lower);
    const double upper_fixed = sweeper.fixed(c, Bound::Upper);
    initial_lower[c] = lower_fixed >= 0 ? lower_fixed : 0;
    initial_upper[c] = upper_fixed >= 0 ? upper_fixed : 1;
  }
  ValueTable optimal(mdp.grid, initial_lower);
  ValueTable upper(mdp.grid, initial_upper);
  const std::size_t length = optimal.line_length();
  std::vector<double> line_lower(length);
  std::vector<double> line_upper(length);
  std::vector<std::uint32_t> policy(cells, 0);
  result.stop_reason = "sweep limit";
  for (std::uint64_t sweep = 1; sweep <= options.max_sweeps; ++sweep) {
    double moved = 0;
    for (std::size_t line = 0; line < optimal.lines(); ++line) {
      for (std::size_t i = 0; i < length; ++i) {
        const std::size_t c = line * length + i;
        line_lower[i] = sweeper.improve(c, optimal, policy[c]);
        std::uint32_t ignored = 0;
        line_upper[i] = std::min(upper[c], sweeper.best_action(c, upper, Bound::Upper, ignored));
        moved = std::max(
            {moved, std::abs(line_lower[i] - optimal[c]), std::abs(line_upper[i] - upper[c])});
      }
      optimal.set_line(line, line_lower.data());
      upper.set_line(line, line_upper.data());
    }
    result.sweeps = sweep;
    const double gap = largest_gap(optimal.values(), upper.values());
    if (options.progress) options.progress(sweep, gap);
    if (gap <= options.gap) {
      result.stop_reason = "gap closed";
      break;
    }
    if (moved <= options.stall) {
      result.stop_reason = "values stopped moving";
      break;
    }
  }
  // The controller's own lower bound: its values from 0, under the policy alone.
  ValueTable lower(mdp.grid, initial_lower);
  for (std::uint64_t sweep = 1; sweep <= options.max_sweeps; ++sweep) {
    double moved = 0;
    double gap = 0;
    for (std::size_t line = 0; line < lower.lines(); ++line) {
      for (std::size_t i = 0; i < length; ++i) {
        const std::size_t c = line * length + i;
        line_lower[i] = sweeper.evaluate(c, lower, policy[c]);
        moved = std::max(moved, std::abs(line_lower[i] - lower[c]));
        gap = std::max(gap, upper[c] - line_lower[i]);
      }
      lower.set_line(line, line_lower.data());
    }
    result.evaluation_sweeps = sweep;
    if (gap <= options.gap || moved <= options.stall) break;
  }
  result.largest_gap = largest_gap(lower.values(), upper.values());
  result.gap_closed = result.largest_gap <= options.gap;
  result.lower = lower.release();
  result.upper = upper.release();
  result.controller.push_back(std::move(policy));
  return result;
}

}  // namespace

Synthesis synthesise(const IntervalMdp& mdp, const model::GuaranteeObjective& objective,
                     const ObjectiveCells& cells, const SynthesisOptions& options) {
  Sweeper sweeper(mdp, cells, mode_of(objective));
  if (objective.steps) return bounded(sweeper, mdp, *objective.steps, options);
  return unbounded(sweeper, mdp, options);
}

}  // namespace oasis::guarantee
