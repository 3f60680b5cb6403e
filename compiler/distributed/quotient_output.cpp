#include "distributed/quotient_output.hpp"

#include <limits>

#include "bisim/quotient.hpp"

namespace oasis::distributed {
namespace {

// The representatives' rows, as each owner sends them: per representative, in the order
// asked, its choice count, then per choice the action, the reward and the (target block,
// probability) pairs.
Bytes representative_rows(const OwnedModel& owned, const Bytes& asked) {
  Bytes rows;
  ByteWriter writer(rows);
  ByteReader reader(asked);
  while (!reader.at_end()) {
    const auto local = reader.get<std::uint32_t>();
    const std::uint32_t first = owned.state_choice_begin[local];
    const std::uint32_t last = owned.state_choice_begin[local + 1];
    writer.put(last - first);
    for (std::uint32_t c = first; c < last; ++c) {
      writer.put(owned.choice_action[c]);
      writer.put(owned.choice_reward[c]);
      writer.put(owned.edge_count[c]);
      for (std::uint32_t e = owned.edge_begin[c]; e < owned.edge_begin[c] + owned.edge_count[c];
           ++e) {
        writer.put(owned.edge_target[e]);
        writer.put(owned.edge_probability[e]);
      }
    }
  }
  return rows;
}

// On rank 0: the model whose state z is block z, with the rows of its representative and
// targets replaced by their blocks; its quotient under the identity partition is the
// quotient of the whole model.
model::ExplicitModel blocks_model(const OwnedModel& owned, const GatheredPartition& gathered,
                                  const std::vector<std::vector<model::BlockIndex>>& asked,
                                  const std::vector<Bytes>& rows) {
  const model::BlockIndex num_blocks = gathered.partition.num_blocks;
  const auto num_actions = static_cast<std::uint32_t>(owned.actions.size());
  model::ExplicitModel blocks;
  blocks.name = owned.name;
  blocks.actions = owned.actions;
  blocks.values = owned.values;
  blocks.states.size = num_blocks;
  for (model::StateIndex s : owned.initial)
    blocks.states.initial.push_back(gathered.partition.block_of[s]);
  model::TransitionBuilder builder(num_blocks, num_actions);
  model::RewardTable rewards;
  rewards.state.assign(num_blocks, RationalPool::kZero);
  std::vector<ValueId> choice_reward(std::size_t{num_blocks} * num_actions, RationalPool::kZero);
  bool any_reward = false;
  for (std::size_t q = 0; q < rows.size(); ++q) {
    ByteReader reader(rows[q]);
    for (model::BlockIndex z : asked[q]) {
      const auto choices = reader.get<std::uint32_t>();
      for (std::uint32_t i = 0; i < choices; ++i) {
        const auto action = reader.get<model::ActionIndex>();
        const auto reward = reader.get<ValueId>();
        choice_reward[std::size_t{z} * num_actions + action] = reward;
        any_reward = any_reward || reward != RationalPool::kZero;
        const auto count = reader.get<std::uint32_t>();
        for (std::uint32_t e = 0; e < count; ++e) {
          const auto block = reader.get<std::uint32_t>();
          builder.add(z, action, gathered.canonical[block], reader.get<ValueId>());
        }
      }
    }
  }
  if (any_reward) rewards.choice = std::move(choice_reward);
  auto matrix = std::make_shared<const model::TransitionMatrix>(builder.finish(blocks.values));
  blocks.contexts.push_back({"default", std::move(matrix), std::move(rewards)});
  return blocks;
}

}  // namespace

std::optional<model::ExplicitModel> gather_quotient(
    const OwnedModel& owned, const std::optional<GatheredPartition>& gathered,
    const Communicator& communicator) {
  const std::uint32_t ranks = communicator.size();
  std::vector<std::vector<model::BlockIndex>> asked(ranks);  // rank 0: per owner, the blocks
  std::vector<Bytes> requests(ranks);
  if (communicator.is_root()) {
    const model::Partition& partition = gathered->partition;
    std::vector<model::StateIndex> representative(partition.num_blocks,
                                                  std::numeric_limits<model::StateIndex>::max());
    for (model::StateIndex s = partition.num_states(); s-- > 0;)
      representative[partition.block_of[s]] = s;
    for (model::BlockIndex z = 0; z < partition.num_blocks; ++z) {
      const std::uint32_t q = owned.ownership.owner(representative[z]);
      asked[q].push_back(z);
      ByteWriter(requests[q]).put(owned.ownership.local(representative[z]));
    }
  }
  const std::vector<Bytes> questions = communicator.exchange(requests);
  std::vector<Bytes> answers(ranks);
  answers[0] = representative_rows(owned, questions[0]);
  const std::vector<Bytes> rows = communicator.exchange(answers);
  if (!communicator.is_root()) return std::nullopt;
  const model::ExplicitModel blocks = blocks_model(owned, *gathered, asked, rows);
  model::Partition identity;
  identity.num_blocks = blocks.num_states();
  identity.block_of.resize(identity.num_blocks);
  for (model::BlockIndex z = 0; z < identity.num_blocks; ++z)
    identity.block_of[z] = z;
  return bisim::build_quotient(blocks, 0, identity);
}

}  // namespace oasis::distributed
