#include "policy/numeric_context.hpp"

#include <algorithm>
#include <cmath>

#include "policy/discounted_iteration.hpp"

namespace oasis::policy {

NumericContext::NumericContext(const model::ExplicitModel& model, std::size_t context)
    : matrix_(model.contexts[context].transitions.get()) {
  // Each distinct rational is converted once; edges and rewards refer to few of them.
  std::vector<double> pool(model.values.size());
  for (ValueId id = 0; id < pool.size(); ++id)
    pool[id] = to_double(model.values[id]);

  const model::RewardTable& rewards = model.contexts[context].rewards;
  const std::uint32_t n = matrix_->num_states;
  const std::uint32_t k = matrix_->num_actions;
  probability_.resize(matrix_->edge_probability.size());
  for (std::size_t e = 0; e < probability_.size(); ++e)
    probability_[e] = pool[matrix_->edge_probability[e]];
  state_reward_.resize(n);
  reward_.resize(std::size_t{n} * k);
  dead_end_.assign(n, 1);
  for (model::StateIndex s = 0; s < n; ++s) {
    state_reward_[s] = pool[rewards.state[s]];
    for (model::ActionIndex a = 0; a < k; ++a) {
      const std::size_t c = std::size_t{s} * k + a;
      // Summed exactly before rounding, as R(s, a) of the model is defined.
      reward_[c] =
          rewards.choice.empty()
              ? state_reward_[s]
              : to_double(model.values[rewards.state[s]] + model.values[rewards.choice[c]]);
      if (matrix_->enabled(s, a)) dead_end_[s] = 0;
    }
  }
}

double NumericContext::q_value(const std::vector<double>& values, model::StateIndex s,
                               model::ActionIndex a, double discount) const {
  double expected = 0;
  for (model::EdgeIndex e = matrix_->edges_begin(s, a); e < matrix_->edges_end(s, a); ++e)
    expected += probability_[e] * values[matrix_->edge_target[e]];
  return reward_[std::size_t{s} * matrix_->num_actions + a] + discount * expected;
}

Greedy greedy(const NumericContext& context, const std::vector<double>& values, model::StateIndex s,
              double discount) {
  return greedy_action(context, values, s, discount);
}

}  // namespace oasis::policy
