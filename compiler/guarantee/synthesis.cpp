#include "guarantee/synthesis.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "guarantee/robust_value.hpp"
#include "guarantee/sweeper.hpp"
#include "guarantee/unbounded_synthesis.hpp"

namespace oasis::guarantee {

double mean(const std::vector<double>& values) {
  double sum = 0;
  for (const double v : values)
    sum += v;
  return values.empty() ? 0.0 : sum / static_cast<double>(values.size());
}

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

namespace {

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

}  // namespace

Synthesis synthesise(const IntervalMdp& mdp, const model::GuaranteeObjective& objective,
                     const ObjectiveCells& cells, const SynthesisOptions& options) {
  if (!objective.steps) return synthesise_unbounded(mdp, cells, sweep_mode(objective), options);
  Sweeper sweeper(mdp, cells, sweep_mode(objective));
  return bounded(sweeper, mdp, *objective.steps, options);
}

}  // namespace oasis::guarantee
