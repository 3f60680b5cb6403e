#pragma once
// One context of an explicit model in doubles, for the iterative solvers: the exact rationals
// are converted once here rather than on every sweep. The CSR structure is shared with the
// model, not copied.

#include <cstdint>
#include <limits>
#include <vector>

#include "model/explicit_model.hpp"

namespace oasis::policy {

// The action of a state with no enabled action: there is nothing to choose.
inline constexpr model::ActionIndex kNoAction = std::numeric_limits<model::ActionIndex>::max();

class NumericContext {
 public:
  NumericContext(const model::ExplicitModel& model, std::size_t context);

  [[nodiscard]] std::uint32_t num_states() const { return matrix_->num_states; }
  [[nodiscard]] std::uint32_t num_actions() const { return matrix_->num_actions; }
  [[nodiscard]] bool enabled(model::StateIndex s, model::ActionIndex a) const {
    return matrix_->enabled(s, a);
  }
  // True when no action is enabled in s (a dead end).
  [[nodiscard]] bool dead_end(model::StateIndex s) const { return dead_end_[s] != 0; }
  // R(s) alone: what a dead end collects on every step.
  [[nodiscard]] double state_reward(model::StateIndex s) const { return state_reward_[s]; }

  // R(s, a) + discount * sum_s' P(s' | s, a) values[s'], for an enabled action.
  [[nodiscard]] double q_value(const std::vector<double>& values, model::StateIndex s,
                               model::ActionIndex a, double discount) const;

 private:
  const model::TransitionMatrix* matrix_;
  std::vector<double> probability_;   // per edge
  std::vector<double> reward_;        // R(s, a) per choice
  std::vector<double> state_reward_;  // R(s) per state
  std::vector<char> dead_end_;
};

struct Greedy {
  model::ActionIndex action = kNoAction;
  double value = 0;  // the largest q-value (that of `action` up to the tie slack)
};

// The best enabled action of a live state for `values`. Ties go to the smallest action index:
// the chosen action is the smallest whose q-value is within kTieSlack * max(1, |max q|) of
// the maximum, so that actions whose q-values are equal in exact arithmetic but differ by
// rounding still resolve to the same action. The slack costs at most
// kTieSlack * max(1, |max q|) / (1 - γ) in optimality (docs/policies.md).
inline constexpr double kTieSlack = 1e-12;
Greedy greedy(const NumericContext& context, const std::vector<double>& values, model::StateIndex s,
              double discount);

}  // namespace oasis::policy
