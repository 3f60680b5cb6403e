#include "policy/solvability.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

namespace oasis::policy {
namespace {

// Headroom below DBL_MAX for R + γ Σ p V and for rounding on the way to the bound.
constexpr double kLargestValue = DBL_MAX / 16;

std::string number_text(double value, int digits = 3) {
  char text[40];
  std::snprintf(text, sizeof text, "%.*g", digits, value);
  return text;
}

double largest_magnitude(const model::ExplicitModel& model, const std::vector<ValueId>& ids,
                         std::vector<bool>& seen) {
  double largest = 0;
  for (const ValueId id : ids) {
    if (seen[id]) continue;
    seen[id] = true;
    largest = std::max(largest, std::fabs(to_double(model.values[id])));
  }
  return largest;
}

double effective_horizon(const ResolvedObjective& objective) {
  if (objective.horizon) return static_cast<double>(*objective.horizon);
  return 1 / (1 - objective.discount);
}

}  // namespace

double reward_bound(const model::ExplicitModel& model) {
  double state = 0;
  double choice = 0;
  for (const model::Context& context : model.contexts) {
    // Per context, so that a value shared by contexts is converted once per context at most.
    std::vector<bool> seen(model.values.size(), false);
    state = std::max(state, largest_magnitude(model, context.rewards.state, seen));
    std::fill(seen.begin(), seen.end(), false);
    choice = std::max(choice, largest_magnitude(model, context.rewards.choice, seen));
  }
  return state + choice;
}

double sweep_bound(const ResolvedObjective& objective, double reward_bound, double tolerance) {
  if (objective.horizon || reward_bound == 0) return 0;
  const double gamma = objective.discount;
  const double threshold = stopping_threshold(objective, tolerance);
  // ‖V_1 - V_0‖ <= max|R| / (1 - γ): dead ends start at their fixed point R(s)/(1 - γ), so
  // a state next to one can move that far in the first sweep.
  // In logarithms, so that huge rewards or tiny thresholds cannot overflow the quotient.
  const double log_ratio = std::log(reward_bound) - std::log(1 - gamma) - std::log(threshold);
  if (log_ratio <= 0) return 1;
  return std::ceil(log_ratio / -std::log(gamma));
}

std::optional<std::string> unsolvable_reason(const model::ExplicitModel& model,
                                             const PolicyOptions& options) {
  ResolvedObjective objective;
  try {
    objective = resolve_objective(model, options);
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  const double rewards = reward_bound(model);
  const double steps = effective_horizon(objective);
  const std::string objective_text =
      objective.horizon ? "a horizon of " + std::to_string(*objective.horizon) + " steps"
                        : "discount " + number_text(objective.discount, 15) +
                              (objective.default_discount ? " (the default)" : "");
  if (!(rewards * steps <= kLargestValue)) {
    return "rewards up to " + number_text(rewards) + " with " + objective_text +
           " give values up to " + number_text(rewards * steps) +
           ", beyond what the catalog's doubles hold (about 1.8e+308); scale the rewards down";
  }
  const double sweeps = sweep_bound(objective, rewards, options.tolerance);
  if (sweeps > options.max_iterations) {
    return "value iteration with " + objective_text + " and rewards up to " + number_text(rewards) +
           " may need " + number_text(sweeps) + " sweeps to reach its " + "tolerance " +
           number_text(options.tolerance) + ", more than its limit of " +
           std::to_string(options.max_iterations) +
           "; use a smaller discount, or 'horizon N' instead";
  }
  return std::nullopt;
}

}  // namespace oasis::policy
