#pragma once
// Which objective a policy maximises: the caller's options, else the model's, else a default.
// Kept apart from the solvers so that value iteration and policy evaluation read the same
// rule and report the same objective.

#include <cstdint>
#include <optional>

#include "model/explicit_model.hpp"

namespace oasis::policy {

struct PolicyOptions {
  // When either is set, these two define the objective and model.objective is ignored: mixing
  // a horizon from one place with a discount from another would be a surprise.
  std::optional<double> discount;
  std::optional<std::uint32_t> horizon;
  // epsilon of the guarantee: the returned greedy policy is epsilon-optimal (docs/policies.md).
  double tolerance = 1e-10;
  std::uint32_t max_iterations = 1'000'000;
};

// Used when neither the options nor the model name an objective. Specs need not give one, and
// 0.95 is a common choice whose effective horizon (~20 steps) suits attention switching.
inline constexpr double kDefaultDiscount = 0.95;

struct ResolvedObjective {
  double discount = kDefaultDiscount;    // in (0, 1); (0, 1] with a horizon
  std::optional<std::uint32_t> horizon;  // set: finite horizon of this many steps (>= 1)
  bool default_discount = false;         // true when kDefaultDiscount was picked
};

// Throws std::invalid_argument with a sentence when the objective cannot be solved: a discount
// outside (0, 1], discount 1 without a horizon (values may be infinite), horizon 0, or a
// tolerance that is not positive.
ResolvedObjective resolve_objective(const model::ExplicitModel& model,
                                    const PolicyOptions& options);
// The same from the model's objective alone (a spec's, before any model is built).
ResolvedObjective resolve_objective(const model::Objective& stated, const PolicyOptions& options);

// The stopping threshold is never below this many units of double rounding of max|V|
// (value_iteration.cpp): a smaller tolerance cannot be told apart from rounding noise.
inline constexpr double kResolutionUlps = 8;

// Stop when successive iterates differ by at most this in the max norm: tolerance(1-γ)/(2γ).
// Then (Puterman 1994, Theorem 6.3.1) the greedy policy of the last iterate is
// tolerance-optimal and the last iterate is within tolerance/2 of the optimal values.
double stopping_threshold(const ResolvedObjective& objective, double tolerance);

}  // namespace oasis::policy
