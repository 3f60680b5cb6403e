#include "verify/policy_check.hpp"

#include <algorithm>
#include <cmath>

#include "oasis/rt/catalog_view.hpp"
#include "verify/number_text.hpp"

namespace oasis::verify {
namespace {

double tolerance_for(const double* value, std::uint32_t blocks) {
  double scale = 1;
  for (std::uint32_t z = 0; z < blocks; ++z)
    scale = std::max(scale, std::fabs(value[z]));
  return 1e-6 * scale;
}

// The value of following `policy` for one more step after `value`.
double step(const NumericQuotient& quotient, const std::vector<double>& value,
            const std::uint32_t* policy, std::uint32_t z, double gamma) {
  return quotient.dead(z) ? quotient.state_reward[z] + gamma * value[z]
                          : quotient.q(value, z, policy[z], gamma);
}

std::optional<std::string> check_discounted(const NumericQuotient& quotient,
                                            const std::uint32_t* policy, const double* stored,
                                            double gamma, double tolerance) {
  const double delta = tolerance * (1 - gamma) / 8;
  std::vector<double> value(quotient.blocks, 0);
  std::vector<double> next(quotient.blocks, 0);
  for (long sweep = 0;; ++sweep) {
    double change = 0;
    for (std::uint32_t z = 0; z < quotient.blocks; ++z) {
      next[z] = step(quotient, value, policy, z, gamma);
      change = std::max(change, std::fabs(next[z] - value[z]));
    }
    value.swap(next);
    if (change <= delta * (1 - gamma) / gamma) break;  // now |value - V^pi| <= delta
    if (sweep > 10'000'000) return "policy evaluation did not converge";
  }
  for (std::uint32_t z = 0; z < quotient.blocks; ++z) {
    if (quotient.dead(z)) continue;
    for (std::uint32_t a = 0; a < quotient.actions; ++a) {
      if (quotient.enabled[std::size_t{z} * quotient.actions + a] == 0) continue;
      const double gain = quotient.q(value, z, a, gamma) - value[z];
      if (gain > tolerance * (1 - gamma) / 2)
        return "the policy is not optimal: in block " + std::to_string(z) + " action " +
               std::to_string(a) + " gains " + number_text(gain) + " over action " +
               std::to_string(policy[z]);
    }
  }
  for (std::uint32_t z = 0; z < quotient.blocks; ++z) {
    if (std::fabs(stored[z] - value[z]) > tolerance)
      return "value[" + std::to_string(z) + "] is " + number_text(stored[z]) +
             ", the policy's value is " + number_text(value[z]);
  }
  return std::nullopt;
}

std::optional<std::string> check_horizon(const NumericQuotient& quotient,
                                         const std::uint32_t* policy, const double* stored,
                                         double gamma, std::uint32_t horizon, double& tolerance) {
  std::vector<double> value(quotient.blocks, 0);
  std::vector<double> next(quotient.blocks, 0);
  std::vector<double> before_last;
  for (std::uint32_t k = 1; k <= horizon; ++k) {
    if (k == horizon) before_last = value;
    for (std::uint32_t z = 0; z < quotient.blocks; ++z) {
      double best = quotient.state_reward[z] + gamma * value[z];  // dead ends stay
      bool first = true;
      for (std::uint32_t a = 0; a < quotient.actions; ++a) {
        if (quotient.enabled[std::size_t{z} * quotient.actions + a] == 0) continue;
        const double q = quotient.q(value, z, a, gamma);
        best = first ? q : std::max(best, q);
        first = false;
      }
      next[z] = best;
    }
    value.swap(next);
  }
  tolerance = tolerance_for(value.data(), quotient.blocks);
  for (std::uint32_t z = 0; z < quotient.blocks; ++z) {
    if (std::fabs(stored[z] - value[z]) > tolerance)
      return "value[" + std::to_string(z) + "] is " + number_text(stored[z]) + ", the optimal " +
             std::to_string(horizon) + "-step value is " + number_text(value[z]);
    if (!quotient.dead(z) && quotient.q(before_last, z, policy[z], gamma) < value[z] - tolerance)
      return "the policy's first step in block " + std::to_string(z) +
             " is not optimal for the horizon";
  }
  return std::nullopt;
}

}  // namespace

double NumericQuotient::q(const std::vector<double>& value, std::uint32_t z, std::uint32_t a,
                          double gamma) const {
  double expected = 0;
  for (const auto& [block, p] : to[std::size_t{z} * actions + a])
    expected += p * value[block];
  return reward[std::size_t{z} * actions + a] + gamma * expected;
}

bool NumericQuotient::dead(std::uint32_t z) const {
  for (std::uint32_t a = 0; a < actions; ++a)
    if (enabled[std::size_t{z} * actions + a] != 0) return false;
  return true;
}

PolicyObjective objective_of(const model::Objective& objective) {
  PolicyObjective result;
  result.horizon = objective.horizon;
  if (objective.discount) {
    result.gamma = to_double(*objective.discount);
  } else if (objective.horizon) {
    result.gamma = 1.0;
  }
  return result;
}

std::optional<std::string> check_policy_and_values(const NumericQuotient& quotient,
                                                   const std::uint32_t* policy, const double* value,
                                                   const PolicyObjective& objective,
                                                   std::string& summary) {
  for (std::uint32_t z = 0; z < quotient.blocks; ++z) {
    const bool dead = quotient.dead(z);
    const std::uint32_t action = policy[z];
    if (dead != (action == rt::kNoAction) ||
        (!dead && (action >= quotient.actions ||
                   quotient.enabled[std::size_t{z} * quotient.actions + action] == 0)))
      return "policy[" + std::to_string(z) + "] is not an action enabled in block " +
             std::to_string(z);
  }
  if (objective.horizon) {
    double tolerance = 0;
    summary = "optimal for horizon " + std::to_string(*objective.horizon);
    return check_horizon(quotient, policy, value, objective.gamma, *objective.horizon, tolerance);
  }
  const double tolerance = tolerance_for(value, quotient.blocks);
  summary = "optimal within " + number_text(tolerance) + " (discount " +
            number_text(objective.gamma) + ")";
  return check_discounted(quotient, policy, value, objective.gamma, tolerance);
}

}  // namespace oasis::verify
