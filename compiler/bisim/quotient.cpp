#include "bisim/quotient.hpp"

#include <algorithm>
#include <limits>

namespace oasis::bisim {

model::ExplicitModel build_quotient(const model::ExplicitModel& model, std::size_t context,
                                    const model::Partition& partition) {
  const model::Context& source = model.contexts[context];
  const model::TransitionMatrix& matrix = *source.transitions;
  const std::uint32_t num_actions = model.num_actions();
  const model::BlockIndex num_blocks = partition.num_blocks;

  model::ExplicitModel quotient;
  quotient.name = model.name;
  quotient.actions = model.actions;
  quotient.objective = model.objective;
  quotient.states.size = num_blocks;
  for (model::BlockIndex z = 0; z < num_blocks; ++z)
    quotient.states.names.push_back("z" + std::to_string(z));
  for (model::StateIndex s : model.states.initial)
    quotient.states.initial.push_back(partition.block_of[s]);
  std::sort(quotient.states.initial.begin(), quotient.states.initial.end());
  quotient.states.initial.erase(
      std::unique(quotient.states.initial.begin(), quotient.states.initial.end()),
      quotient.states.initial.end());

  // The smallest member of each block represents it.
  std::vector<model::StateIndex> representative(num_blocks,
                                                std::numeric_limits<model::StateIndex>::max());
  for (model::StateIndex s = partition.num_states(); s-- > 0;)
    representative[partition.block_of[s]] = s;

  model::TransitionBuilder builder(num_blocks, num_actions);
  model::RewardTable rewards;
  rewards.state.resize(num_blocks);
  if (!source.rewards.choice.empty()) rewards.choice.resize(std::size_t{num_blocks} * num_actions);
  for (model::BlockIndex z = 0; z < num_blocks; ++z) {
    const model::StateIndex r = representative[z];
    rewards.state[z] = quotient.values.intern(model.values[source.rewards.state[r]]);
    for (model::ActionIndex a = 0; a < num_actions; ++a) {
      if (!rewards.choice.empty()) {
        rewards.choice[std::size_t{z} * num_actions + a] = quotient.values.intern(
            model.values[source.rewards.choice[std::size_t{r} * num_actions + a]]);
      }
      // Edges into the same block are merged by the builder, adding probabilities exactly.
      for (model::EdgeIndex e = matrix.edges_begin(r, a); e < matrix.edges_end(r, a); ++e) {
        builder.add(z, a, partition.block_of[matrix.edge_target[e]],
                    quotient.values.intern(model.values[matrix.edge_probability[e]]));
      }
    }
  }
  auto transitions =
      std::make_shared<const model::TransitionMatrix>(builder.finish(quotient.values));
  quotient.contexts.push_back({source.name, std::move(transitions), std::move(rewards)});
  quotient.switching.matrix = {Rational(1)};
  quotient.switching.prior = {Rational(1)};
  return quotient;
}

}  // namespace oasis::bisim
