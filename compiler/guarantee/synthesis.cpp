#include "guarantee/synthesis.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <thread>

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

// Covers, with a wide margin, the outward rounding of the two robust values compared when an
// action is skipped on its cached value (each is within about 1e-12 of exact even for rows of
// a thousand entries per axis in four dimensions).
constexpr double kLipschitzSlack = 1e-9;

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

  // The iterations' update: the greatest value over the actions at `cell`, trying `action`
  // first; `action` becomes the best one only if it gains more than `switch_gain` over it (the
  // lower bound's controller keeps its action unless another is really better).
  //
  // Actions are skipped when they cannot win: a robust value moves by at most as much as the
  // values it reads (it is 1-Lipschitz in the largest change), so an action whose value, when
  // last computed, was below the best by more than everything has moved since, still is.
  // ValueTable::drift() bounds that movement. This skips most actions once the values settle.
  // The cache belongs to one table: a Sweeper's update() always reads the same ValueTable.
  double update(std::size_t cell, const ValueTable& values, Bound bound, std::uint32_t& action,
                double switch_gain) {
    const double constant = fixed(cell, bound);
    if (constant >= 0) return constant;
    const RobustGame g = game(bound);
    const std::size_t actions = mdp_.actions.size();
    if (cached_value_.empty()) {
      cached_value_.assign(mdp_.grid.cells * actions, std::numeric_limits<double>::infinity());
      cached_drift_.assign(mdp_.grid.cells * actions, 0);
    }
    const auto value_of = [&](std::size_t a) {
      const double q = robust_value(mdp_, mdp_.row(cell, a), values, g, scratch_);
      cached_value_[cell * actions + a] = q;
      cached_drift_[cell * actions + a] = values.drift();
      return q;
    };
    const double current = value_of(action);
    double best = current;
    std::uint32_t best_index = action;
    for (std::size_t a = 0; a < actions; ++a) {
      if (a == action) continue;
      const std::size_t slot = cell * actions + a;
      const double reach =
          cached_value_[slot] + (values.drift() - cached_drift_[slot]) + kLipschitzSlack;
      if (reach < best) continue;
      const double q = value_of(a);
      if (q > best) {
        best = q;
        best_index = static_cast<std::uint32_t>(a);
      }
    }
    if (best > current + switch_gain) action = best_index;
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
  // Per (cell, action): its value when last computed, and the table's drift then.
  std::vector<double> cached_value_;
  std::vector<double> cached_drift_;
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

// One sequence of interval iteration, line by line (block Gauss-Seidel: a line's new values
// are computed from the values before it, then stored), until no value moves by more than the
// stall threshold or the sweep limit. `update(cell, table)` is the new value of a cell.
template <typename Update>
std::uint64_t iterate(ValueTable& table, const SynthesisOptions& options, const Update& update,
                      std::string& stop_reason) {
  const std::size_t length = table.line_length();
  std::vector<double> line_values(length);
  stop_reason = "sweep limit";
  for (std::uint64_t sweep = 1; sweep <= options.max_sweeps; ++sweep) {
    double moved = 0;
    for (std::size_t line = 0; line < table.lines(); ++line) {
      for (std::size_t i = 0; i < length; ++i) {
        const std::size_t c = line * length + i;
        line_values[i] = update(c, table);
        moved = std::max(moved, std::abs(line_values[i] - table[c]));
      }
      table.set_line(line, line_values.data());
    }
    if (options.progress) options.progress(sweep, moved);
    if (moved <= options.stall) {
      stop_reason = "values stopped moving";
      return sweep;
    }
  }
  return options.max_sweeps;
}

// Interval iteration: the lower bound from below and the upper bound from above, on two
// threads (they share nothing but the rows). Every iterate of either is a proven bound
// (docs/guarantees.md), so any stop is sound; the stop rule only decides how tight they are.
Synthesis unbounded(const IntervalMdp& mdp, const ObjectiveCells& cells, Mode mode,
                    const SynthesisOptions& options) {
  const std::size_t count = mdp.grid.cells;
  Synthesis result;
  Sweeper lower_sweeper(mdp, cells, mode);
  Sweeper upper_sweeper(mdp, cells, mode);
  std::vector<double> initial_lower(count);
  std::vector<double> initial_upper(count);
  for (std::size_t c = 0; c < count; ++c) {
    const double lower_fixed = lower_sweeper.fixed(c, Bound::Lower);
    const double upper_fixed = upper_sweeper.fixed(c, Bound::Upper);
    initial_lower[c] = lower_fixed >= 0 ? lower_fixed : 0;
    initial_upper[c] = upper_fixed >= 0 ? upper_fixed : 1;
  }
  ValueTable optimal(mdp.grid, initial_lower);
  ValueTable upper(mdp.grid, initial_upper);
  std::vector<std::uint32_t> policy(count, 0);
  std::vector<std::uint32_t> upper_choice(count, 0);  // tried first: last sweep's best
  std::string upper_reason;
  std::uint64_t upper_sweeps = 0;
  auto upper_work = [&] {
    SynthesisOptions quiet = options;
    quiet.progress = nullptr;
    upper_sweeps = iterate(
        upper, quiet,
        [&](std::size_t c, const ValueTable& values) {
          return std::min(values[c],
                          upper_sweeper.update(c, values, Bound::Upper, upper_choice[c], 0));
        },
        upper_reason);
  };
  std::thread upper_thread;
  if (options.jobs > 1) upper_thread = std::thread(upper_work);
  result.sweeps = iterate(
      optimal, options,
      [&](std::size_t c, const ValueTable& values) {
        return lower_sweeper.update(c, values, Bound::Lower, policy[c], kSwitchGain);
      },
      result.stop_reason);
  if (upper_thread.joinable()) {
    upper_thread.join();
  } else {
    upper_work();
  }
  result.sweeps = std::max(result.sweeps, upper_sweeps);
  // The controller's own lower bound: its values from 0, under the policy alone.
  ValueTable lower(mdp.grid, initial_lower);
  result.evaluation_sweeps = iterate(
      lower, options,
      [&](std::size_t c, const ValueTable& values) {
        return lower_sweeper.evaluate(c, values, policy[c]);
      },
      result.stop_reason);
  result.largest_gap = largest_gap(lower.values(), upper.values());
  result.gap_closed = result.largest_gap <= options.gap;
  if (result.gap_closed) result.stop_reason = "gap closed";
  result.lower = lower.release();
  result.upper = upper.release();
  result.controller.push_back(std::move(policy));
  return result;
}

}  // namespace

Synthesis synthesise(const IntervalMdp& mdp, const model::GuaranteeObjective& objective,
                     const ObjectiveCells& cells, const SynthesisOptions& options) {
  if (!objective.steps) return unbounded(mdp, cells, mode_of(objective), options);
  Sweeper sweeper(mdp, cells, mode_of(objective));
  return bounded(sweeper, mdp, *objective.steps, options);
}

}  // namespace oasis::guarantee
