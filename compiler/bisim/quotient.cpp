#include "bisim/quotient.hpp"

#include <algorithm>
#include <limits>

namespace oasis::bisim {
namespace {

constexpr ValueId kNotInterned = std::numeric_limits<ValueId>::max();

// The representatives are spread over the whole model, and with many blocks reading their
// rows and their targets' blocks is a cache miss each: those of the blocks a few ahead of `z`
// are asked for first (offsets, then edges, then the targets' blocks).
void prefetch_representatives(const model::TransitionMatrix& matrix,
                              const model::Partition& partition,
                              const std::vector<model::StateIndex>& representative,
                              model::BlockIndex z) {
  const std::size_t k = matrix.num_actions;
  if (z + 16 < representative.size())
    __builtin_prefetch(&matrix.choice_begin[representative[z + 16] * k]);
  if (z + 8 < representative.size()) {
    const model::EdgeIndex first = matrix.choice_begin[representative[z + 8] * k];
    __builtin_prefetch(&matrix.edge_target[first]);
    __builtin_prefetch(&matrix.edge_probability[first]);
  }
  if (z + 4 < representative.size()) {
    const std::size_t c = representative[z + 4] * k;
    for (model::EdgeIndex e = matrix.choice_begin[c]; e < matrix.choice_begin[c + k]; ++e)
      __builtin_prefetch(&partition.block_of[matrix.edge_target[e]]);
  }
}

}  // namespace

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
  // The model's values are few and repeat on every row: each is interned in the quotient once.
  std::vector<ValueId> value_in_quotient(model.values.size(), kNotInterned);
  const auto value = [&](ValueId id) {
    ValueId& interned = value_in_quotient[id];
    if (interned == kNotInterned) interned = quotient.values.intern(model.values[id]);
    return interned;
  };
  for (model::BlockIndex z = 0; z < num_blocks; ++z) {
    prefetch_representatives(matrix, partition, representative, z);
    const model::StateIndex r = representative[z];
    rewards.state[z] = value(source.rewards.state[r]);
    for (model::ActionIndex a = 0; a < num_actions; ++a) {
      if (!rewards.choice.empty())
        rewards.choice[std::size_t{z} * num_actions + a] =
            value(source.rewards.choice[std::size_t{r} * num_actions + a]);
      // Edges into the same block are merged by the builder, adding probabilities exactly.
      for (model::EdgeIndex e = matrix.edges_begin(r, a); e < matrix.edges_end(r, a); ++e) {
        builder.add(z, a, partition.block_of[matrix.edge_target[e]],
                    value(matrix.edge_probability[e]));
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
