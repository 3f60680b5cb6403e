#pragma once
// Is a catalog's policy optimal for its quotient, and are its values right? Checked by policy
// evaluation written here, apart from the compiler's value iteration (compiler/policy/):
//  * discounted: V^pi by iteration to within delta = tol (1 - γ) / 8, then the Bellman
//    residual max_a Q(z, a) - V^pi(z) <= tol (1 - γ) / 2 for every block, which proves
//    V* - V^pi <= 3/4 tol; and |value - V^pi| <= tol;
//  * horizon H: V_H by backward induction; value within tol of it and the policy's first
//    step within tol of optimal;
// with tol = 1e-6 max(1, max|V|). A block with no enabled action must have kNoAction and
// stays put, collecting its state reward.

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "model/explicit_model.hpp"

namespace oasis::verify {

// A quotient in doubles, as the checker rebuilt it (from the model, or from a catalog's rows
// once they are checked).
struct NumericQuotient {
  std::uint32_t blocks = 0;
  std::uint32_t actions = 0;
  std::vector<std::uint8_t> enabled;                              // [blocks * actions]
  std::vector<std::vector<std::pair<std::uint32_t, double>>> to;  // [blocks * actions]
  std::vector<double> reward;                                     // [blocks * actions] R^Z
  std::vector<double> state_reward;                               // [blocks] R(s)

  [[nodiscard]] double q(const std::vector<double>& value, std::uint32_t z, std::uint32_t a,
                         double gamma) const;
  [[nodiscard]] bool dead(std::uint32_t z) const;
};

struct PolicyObjective {
  double gamma = 0.95;
  std::optional<std::uint32_t> horizon;
};

// The compiler's rule (docs/policies.md), restated here: the spec's discount or horizon,
// else discount 0.95.
PolicyObjective objective_of(const model::Objective& objective);

// nullopt when the policy and values hold; otherwise why not. `summary` says what was shown
// ("optimal within 1e-05 (discount 0.9)").
std::optional<std::string> check_policy_and_values(const NumericQuotient& quotient,
                                                   const std::uint32_t* policy, const double* value,
                                                   const PolicyObjective& objective,
                                                   std::string& summary);

}  // namespace oasis::verify
