#include "model/statistics.hpp"

namespace oasis::model {

std::vector<ContextStatistics> context_statistics(const ExplicitModel& model) {
  std::vector<ContextStatistics> result;
  for (std::size_t c = 0; c < model.contexts.size(); ++c) {
    const TransitionMatrix& matrix = *model.contexts[c].transitions;
    ContextStatistics stats;
    stats.states = model.num_states();
    stats.actions = model.num_actions();
    stats.transitions = matrix.num_edges();
    // Rewards are few distinct values: compare ids first, rationals only for new ids.
    std::vector<bool> seen(model.values.size(), false);
    auto consider = [&](const Rational& value) {
      if (!stats.reward_min || value < *stats.reward_min) stats.reward_min = value;
      if (!stats.reward_max || value > *stats.reward_max) stats.reward_max = value;
    };
    const RewardTable& rewards = model.contexts[c].rewards;
    for (StateIndex s = 0; s < model.num_states(); ++s) {
      for (ActionIndex a = 0; a < model.num_actions(); ++a) {
        if (!matrix.enabled(s, a)) continue;
        ++stats.choices;
        if (rewards.choice.empty()) {
          const ValueId id = rewards.state[s];
          if (!seen[id]) consider(model.values[id]);
          seen[id] = true;
        } else {
          consider(model.reward(c, s, a));
        }
      }
    }
    result.push_back(std::move(stats));
  }
  return result;
}

}  // namespace oasis::model
