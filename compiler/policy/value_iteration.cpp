#include "policy/value_iteration.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace oasis::policy {
namespace {

// Doubles cannot resolve changes much below an ulp of the largest value: iterates that close
// to the fixed point may step back and forth by an ulp forever. The stopping threshold never
// goes below a few ulps of max|V| (docs/policies.md).
double resolution_floor(const std::vector<double>& value) {
  double largest = 0;
  for (const double v : value)
    largest = std::max(largest, std::abs(v));
  return kResolutionUlps * std::numeric_limits<double>::epsilon() * largest;
}

// Jacobi sweeps from V = 0: the stopping bound of objective.hpp is the textbook one for
// Jacobi updates, which Gauss-Seidel would change.
void discounted(const NumericContext& context, const PolicyOptions& options, Policy& policy) {
  const double gamma = policy.objective.discount;
  const double threshold = stopping_threshold(policy.objective, options.tolerance);
  const std::uint32_t n = context.num_states();
  std::vector<double>& value = policy.value;
  value.assign(n, 0);
  // Dead ends hold their fixed point from the start: R(s) + γ V(s) = V(s).
  for (model::StateIndex s = 0; s < n; ++s) {
    if (context.dead_end(s)) value[s] = context.state_reward(s) / (1 - gamma);
  }
  std::vector<double> next = value;
  while (policy.iterations < options.max_iterations) {
    double change = 0;
    for (model::StateIndex s = 0; s < n; ++s) {
      if (context.dead_end(s)) continue;
      double best = 0;
      bool first = true;
      for (model::ActionIndex a = 0; a < context.num_actions(); ++a) {
        if (!context.enabled(s, a)) continue;
        const double q = context.q_value(value, s, a, gamma);
        if (first || q > best) best = q;
        first = false;
      }
      next[s] = best;
      change = std::max(change, std::abs(best - value[s]));
    }
    std::swap(value, next);
    ++policy.iterations;
    policy.residual = change;
    if (change <= std::max(threshold, resolution_floor(value))) {
      policy.converged = true;
      break;
    }
  }
  // Greedy with respect to the last iterate, the policy the bound speaks of.
  policy.action.assign(n, kNoAction);
  for (model::StateIndex s = 0; s < n; ++s) {
    if (!context.dead_end(s)) policy.action[s] = greedy(context, value, s, gamma).action;
  }
}

// V_0 = 0 and V_k = max_a [R + γ P V_{k-1}]; the actions stored are those of step H.
void finite_horizon(const NumericContext& context, Policy& policy) {
  const double gamma = policy.objective.discount;
  const std::uint32_t horizon = *policy.objective.horizon;
  const std::uint32_t n = context.num_states();
  std::vector<double> previous(n, 0);
  std::vector<double> current(n, 0);
  policy.action.assign(n, kNoAction);
  for (std::uint32_t step = 1; step <= horizon; ++step) {
    const bool last = step == horizon;
    for (model::StateIndex s = 0; s < n; ++s) {
      if (context.dead_end(s)) {
        current[s] = context.state_reward(s) + gamma * previous[s];
        continue;
      }
      const Greedy best = greedy(context, previous, s, gamma);
      current[s] = best.value;
      if (last) policy.action[s] = best.action;
    }
    std::swap(previous, current);
  }
  policy.value = std::move(previous);
  policy.iterations = horizon;
  policy.converged = true;
  policy.residual = 0;
}

}  // namespace

Policy solve(const model::ExplicitModel& model, std::size_t context, const PolicyOptions& options) {
  Policy policy;
  policy.objective = resolve_objective(model, options);
  const NumericContext numeric(model, context);
  if (policy.objective.horizon) {
    finite_horizon(numeric, policy);
  } else {
    discounted(numeric, options, policy);
  }
  return policy;
}

}  // namespace oasis::policy
