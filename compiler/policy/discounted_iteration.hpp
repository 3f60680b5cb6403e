#pragma once
// Value iteration for a discounted objective, and the greedy action, over any form of a
// context's rows: a NumericContext (the materialised CSR rows) or rows kept in another form
// (geom/grid_product_rows.hpp through pipeline/). A context offers num_states(),
// num_actions(), enabled(s, a), dead_end(s), state_reward(s) and
// q_value(values, s, a, discount) = R(s, a) + discount * Σ P(s, a, t) values[t]. A context
// whose q-values read sums made ahead from the values (geom/polytope_walk_rows.hpp) also
// offers begin_sweep(values), called before every sweep. The sweeps, the stopping rule and
// the tie rule are the same whatever the form (docs/policies.md).

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "policy/numeric_context.hpp"
#include "policy/objective.hpp"

namespace oasis::policy {

// Tells a context that offers it that a sweep over `values` begins.
template <class Context>
void begin_sweep(const Context& context, const std::vector<double>& values) {
  if constexpr (requires { context.begin_sweep(values); }) context.begin_sweep(values);
}

// The best enabled action of a live state for `values` (the tie rule of numeric_context.hpp).
template <class Context>
Greedy greedy_action(const Context& context, const std::vector<double>& values, model::StateIndex s,
                     double discount) {
  Greedy best;
  for (model::ActionIndex a = 0; a < context.num_actions(); ++a) {
    if (!context.enabled(s, a)) continue;
    const double q = context.q_value(values, s, a, discount);
    if (best.action == kNoAction || q > best.value) best.value = q;
    if (best.action == kNoAction) best.action = a;
  }
  if (best.action == kNoAction) return best;
  // Second pass: the smallest action within the slack of the maximum.
  const double floor = best.value - kTieSlack * std::max(1.0, std::abs(best.value));
  for (model::ActionIndex a = 0; a < context.num_actions(); ++a) {
    if (context.enabled(s, a) && context.q_value(values, s, a, discount) >= floor) {
      best.action = a;
      break;
    }
  }
  return best;
}

// Doubles cannot resolve changes much below an ulp of the largest value: iterates that close
// to the fixed point may step back and forth by an ulp forever. The stopping threshold never
// goes below a few ulps of max|V| (docs/policies.md).
inline double resolution_floor(const std::vector<double>& value) {
  double largest = 0;
  for (const double v : value)
    largest = std::max(largest, std::abs(v));
  return kResolutionUlps * std::numeric_limits<double>::epsilon() * largest;
}

// One Jacobi sweep, next = T value over the live states: each takes its largest q-value (the
// first action to reach it goes into `chosen`). Returns max |next - value|.
template <class Context>
double full_backup(const Context& context, double gamma, const std::vector<double>& value,
                   std::vector<double>& next, std::vector<model::ActionIndex>& chosen) {
  begin_sweep(context, value);
  double change = 0;
  for (model::StateIndex s = 0; s < context.num_states(); ++s) {
    if (context.dead_end(s)) continue;
    double best = 0;
    chosen[s] = kNoAction;
    for (model::ActionIndex a = 0; a < context.num_actions(); ++a) {
      if (!context.enabled(s, a)) continue;
      const double q = context.q_value(value, s, a, gamma);
      if (chosen[s] == kNoAction || q > best) {
        best = q;
        chosen[s] = a;
      }
    }
    next[s] = best;
    change = std::max(change, std::abs(best - value[s]));
  }
  return change;
}

// `value` filled with `start`, but dead ends at their fixed point: R(s) + γ V(s) = V(s).
template <class Context>
void initial_values(const Context& context, double gamma, double start,
                    std::vector<double>& value) {
  value.assign(context.num_states(), start);
  for (model::StateIndex s = 0; s < context.num_states(); ++s) {
    if (context.dead_end(s)) value[s] = context.state_reward(s) / (1 - gamma);
  }
}

// Jacobi sweeps from V = 0 into `value`; true when the stopping rule held within
// `max_iterations`. The stopping bound of objective.hpp is the textbook one for Jacobi
// updates, which Gauss-Seidel would change.
template <class Context>
bool discounted_iteration(const Context& context, double gamma, double threshold,
                          std::uint32_t max_iterations, std::vector<double>& value,
                          std::uint32_t& iterations, double& residual) {
  initial_values(context, gamma, 0.0, value);
  std::vector<double> next = value;
  std::vector<model::ActionIndex> chosen(context.num_states(), kNoAction);
  while (iterations < max_iterations) {
    residual = full_backup(context, gamma, value, next, chosen);
    std::swap(value, next);
    ++iterations;
    if (residual <= std::max(threshold, resolution_floor(value))) return true;
  }
  return false;
}

// Modified policy iteration (Puterman 1994, Section 6.5) into `value`: a full Bellman backup
// fixes a greedy policy, then `evaluations` in-place sweeps of that policy alone (one q-value
// per state instead of one per action) move the values on. It starts from min(0, min R) /
// (1 - γ), below the optimum, so that the iterates rise to it. Every round ends with a full
// backup V = T W, and the stopping rule is that of discounted_iteration() on it: ||T W - W||
// at most the threshold, so the same bound holds (Theorem 6.3.1 asks nothing of W). The
// values differ from Jacobi's in the last bits; it is the solver of rows that are dear to
// evaluate.
template <class Context>
bool modified_policy_iteration(const Context& context, double gamma, double threshold,
                               std::uint32_t max_rounds, std::uint32_t evaluations,
                               std::vector<double>& value, std::uint32_t& rounds,
                               double& residual) {
  double lowest = 0;
  for (model::StateIndex s = 0; s < context.num_states(); ++s)
    lowest = std::min(lowest, context.state_reward(s));
  initial_values(context, gamma, lowest / (1 - gamma), value);
  std::vector<double> next = value;
  std::vector<model::ActionIndex> chosen(context.num_states(), kNoAction);
  while (rounds < max_rounds) {
    residual = full_backup(context, gamma, value, next, chosen);
    std::swap(value, next);
    ++rounds;
    if (residual <= std::max(threshold, resolution_floor(value))) return true;
    for (std::uint32_t sweep = 0; sweep < evaluations; ++sweep) {
      // In place: a context with sums made ahead reads them as of the sweep's start, and
      // any values W keep the bound (above), so that is only a matter of speed.
      begin_sweep(context, value);
      for (model::StateIndex s = 0; s < context.num_states(); ++s) {
        if (!context.dead_end(s)) value[s] = context.q_value(value, s, chosen[s], gamma);
      }
    }
  }
  return false;
}

// The greedy action of every live state for `value`; kNoAction for dead ends.
template <class Context>
std::vector<model::ActionIndex> greedy_actions(const Context& context,
                                               const std::vector<double>& value, double gamma) {
  std::vector<model::ActionIndex> action(context.num_states(), kNoAction);
  begin_sweep(context, value);
  for (model::StateIndex s = 0; s < context.num_states(); ++s) {
    if (!context.dead_end(s)) action[s] = greedy_action(context, value, s, gamma).action;
  }
  return action;
}

}  // namespace oasis::policy
