#pragma once
// Optimal policies of one context of an explicit MDP, in doubles: value iteration for a
// discounted objective, backward induction for a finite horizon. docs/policies.md states the
// guarantees; in short, a converged discounted result is `tolerance`-optimal.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "model/explicit_model.hpp"
#include "policy/numeric_context.hpp"
#include "policy/objective.hpp"

namespace oasis::policy {

struct Policy {
  // One action per state; kNoAction for states with no enabled action. With a finite horizon
  // H this is the first-step action of the optimal H-step plan, used as a stationary
  // (receding-horizon) policy.
  std::vector<model::ActionIndex> action;
  // Discounted: the last iterate, within tolerance/2 of the optimal values when converged.
  // Finite horizon: the optimal H-step values.
  std::vector<double> value;
  std::uint32_t iterations = 0;  // sweeps (finite horizon: H)
  bool converged = false;        // always true for a finite horizon
  double residual = 0;           // max |V_n - V_{n-1}| of the last sweep; 0 for a horizon
  ResolvedObjective objective;   // what was solved, including whether the discount defaulted
};

// Throws std::invalid_argument when the objective cannot be solved (resolve_objective).
// States with no enabled action collect their state reward R(s) on every step: value
// R(s)/(1-γ), or R(s)(1 + γ + ... + γ^(H-1)) with a horizon.
Policy solve(const model::ExplicitModel& model, std::size_t context,
             const PolicyOptions& options = {});

}  // namespace oasis::policy
