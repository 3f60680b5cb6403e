#include "policy/policy_evaluation.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "policy/numeric_context.hpp"

namespace oasis::policy {

std::vector<double> evaluate(const model::ExplicitModel& model, std::size_t context,
                             const std::vector<model::ActionIndex>& policy,
                             const PolicyOptions& options) {
  const ResolvedObjective objective = resolve_objective(model, options);
  const NumericContext numeric(model, context);
  const std::uint32_t n = numeric.num_states();
  if (policy.size() != n) {
    throw std::invalid_argument("the policy has " + std::to_string(policy.size()) +
                                " actions for " + std::to_string(n) + " states");
  }
  for (model::StateIndex s = 0; s < n; ++s) {
    if (numeric.dead_end(s)) continue;
    if (policy[s] >= numeric.num_actions() || !numeric.enabled(s, policy[s])) {
      throw std::invalid_argument("the policy's action in state " + model.states.name(s) +
                                  " is not enabled there");
    }
  }
  const double gamma = objective.discount;
  // One step of following π; dead ends stay where they are and collect R(s).
  auto step = [&](const std::vector<double>& from, model::StateIndex s) {
    return numeric.dead_end(s) ? numeric.state_reward(s) + gamma * from[s]
                               : numeric.q_value(from, s, policy[s], gamma);
  };
  std::vector<double> value(n, 0);
  std::vector<double> next(n, 0);
  if (objective.horizon) {
    for (std::uint32_t k = 0; k < *objective.horizon; ++k) {
      for (model::StateIndex s = 0; s < n; ++s)
        next[s] = step(value, s);
      std::swap(value, next);
    }
    return value;
  }
  const double threshold = stopping_threshold(objective, options.tolerance);
  for (std::uint32_t k = 0; k < options.max_iterations; ++k) {
    double change = 0;
    for (model::StateIndex s = 0; s < n; ++s) {
      next[s] = step(value, s);
      change = std::max(change, std::abs(next[s] - value[s]));
    }
    std::swap(value, next);
    if (change <= threshold) break;
  }
  return value;
}

std::vector<model::ActionIndex> lift(const std::vector<model::ActionIndex>& abstract_policy,
                                     const model::Partition& partition) {
  if (abstract_policy.size() != partition.num_blocks) {
    throw std::invalid_argument("the abstract policy has " +
                                std::to_string(abstract_policy.size()) + " actions for " +
                                std::to_string(partition.num_blocks) + " blocks");
  }
  std::vector<model::ActionIndex> lifted(partition.num_states());
  for (model::StateIndex s = 0; s < partition.num_states(); ++s)
    lifted[s] = abstract_policy[partition.block_of[s]];
  return lifted;
}

}  // namespace oasis::policy
