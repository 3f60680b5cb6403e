#pragma once
// The value of a fixed stationary policy, and policies of a quotient carried back to the
// states of the full model.

#include <cstddef>
#include <vector>

#include "model/explicit_model.hpp"
#include "model/partition.hpp"
#include "policy/objective.hpp"

namespace oasis::policy {

// V^π of one context under the objective of resolve_objective (which may throw
// std::invalid_argument). Discounted: Jacobi iteration of V <- R_π + γ P_π V from V = 0 until
// successive iterates differ by at most tolerance(1-γ)/(2γ), which puts the result within
// tolerance/2 of V^π (or options.max_iterations sweeps). Finite horizon H: the H-step value of
// following π at every step. States with no enabled action collect R(s) on every step, as in
// solve(); their entry of `policy` is ignored. Throws std::invalid_argument when `policy` has
// the wrong size or names an action that is not enabled in a state with enabled actions.
std::vector<double> evaluate(const model::ExplicitModel& model, std::size_t context,
                             const std::vector<model::ActionIndex>& policy,
                             const PolicyOptions& options = {});

// π(s) = π^Z(block(s)): the policy of a quotient over `partition`'s blocks as a policy of the
// full model. When the partition is a bisimulation, members of a block enable the same actions
// and the lifted policy has, at every state, the value the quotient policy has at its block.
std::vector<model::ActionIndex> lift(const std::vector<model::ActionIndex>& abstract_policy,
                                     const model::Partition& partition);

}  // namespace oasis::policy
