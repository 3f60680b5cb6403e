#pragma once
// Can the policies of a model be solved in doubles? Checked before anything is solved, so that
// `oasisc check` refuses what `oasisc compile` could not do, with the same words:
//  * the objective itself (resolve_objective: a discount in (0, 1), 1 only with a horizon);
//  * values must stay finite: |V| <= max|R(s, a)| times the effective horizon (H steps, or
//    1/(1 - γ) when discounted), with room to spare for the Bellman sums;
//  * discounted value iteration must be able to stop within its sweep limit: from V = 0 the
//    change of sweep k is at most γ^k max|R| / (1 - γ), and it stops once the change is at
//    most ε(1 - γ)/(2γ) (docs/policies.md), so ln(2γ max|R| / (ε(1 - γ)^2)) / -ln γ sweeps
//    always suffice. A discount so close to 1 that this passes the limit is refused.

#include <optional>
#include <string>

#include "model/explicit_model.hpp"
#include "policy/objective.hpp"

namespace oasis::policy {

// The largest |R(s, a)| over every context, bounded above by max|R(s)| + max|R(s, a) - R(s)|
// (exact per value, summed in doubles). Cost: one pass over the reward tables' ids.
double reward_bound(const model::ExplicitModel& model);

// Sweeps that discounted value iteration needs at most (0 for a finite horizon or no reward).
double sweep_bound(const ResolvedObjective& objective, double reward_bound, double tolerance);

// nullopt when every context can be solved with `options`; otherwise one sentence saying why
// not and what to change.
std::optional<std::string> unsolvable_reason(const model::ExplicitModel& model,
                                             const PolicyOptions& options = {});

}  // namespace oasis::policy
