#include "policy/value_iteration.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "policy/discounted_iteration.hpp"

namespace oasis::policy {
namespace {

// Value iteration (discounted_iteration.hpp) on the CSR rows.
void discounted(const NumericContext& context, const PolicyOptions& options, Policy& policy) {
  const double gamma = policy.objective.discount;
  const double threshold = stopping_threshold(policy.objective, options.tolerance);
  policy.converged = discounted_iteration(context, gamma, threshold, options.max_iterations,
                                          policy.value, policy.iterations, policy.residual);
  // Greedy with respect to the last iterate, the policy the bound speaks of.
  policy.action = greedy_actions(context, policy.value, gamma);
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
