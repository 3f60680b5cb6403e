#include "verify/unlabelled_check.hpp"

#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>

namespace oasis::verify {
namespace {

using model::BlockIndex;
using model::StateIndex;

// One choice: its reward R(s, a) and its probability of reaching each class, classes ascending.
using ChoiceValue = std::pair<Rational, std::map<std::uint32_t, Rational>>;
using ChoiceSet = std::set<ChoiceValue>;

ChoiceSet choices_of(const model::ExplicitModel& model, std::size_t context,
                     const std::vector<std::uint32_t>& class_of, StateIndex s) {
  const model::TransitionMatrix& matrix = *model.contexts[context].transitions;
  ChoiceSet result;
  for (model::ActionIndex a = 0; a < model.num_actions(); ++a) {
    if (!matrix.enabled(s, a)) continue;
    ChoiceValue choice;
    choice.first = model.reward(context, s, a);
    for (model::EdgeIndex e = matrix.edges_begin(s, a); e < matrix.edges_end(s, a); ++e)
      choice.second[class_of[matrix.edge_target[e]]] += model.values[matrix.edge_probability[e]];
    result.insert(std::move(choice));
  }
  return result;
}

Violation pair_violation(const model::ExplicitModel& model, const model::Partition& partition,
                         ViolationKind kind, StateIndex first, StateIndex other) {
  Violation v;
  v.kind = kind;
  v.state = first;
  v.other_state = other;
  v.block = partition.block_of[first];
  v.message = "states " + model.states.name(first) + " and " + model.states.name(other) +
              " share " + describe_block(model, partition, *v.block) + " but ";
  return v;
}

// What tells apart states with no enabled action: their state reward (R(s) with no action),
// as in Definition 1's check; nullopt for a state that has a choice.
std::optional<Rational> alone_reward(const model::ExplicitModel& model, std::size_t context,
                                     StateIndex s) {
  const model::TransitionMatrix& matrix = *model.contexts[context].transitions;
  for (model::ActionIndex a = 0; a < model.num_actions(); ++a) {
    if (matrix.enabled(s, a)) return std::nullopt;
  }
  return model.values[model.contexts[context].rewards.state[s]];
}

std::uint32_t label_of(const std::vector<std::uint32_t>& label_class, StateIndex s) {
  return label_class.empty() ? 0 : label_class[s];
}

}  // namespace

VerificationResult check_unlabelled_bisimulation(const model::ExplicitModel& model,
                                                 std::size_t context,
                                                 const model::Partition& partition,
                                                 const std::vector<std::uint32_t>& label_class) {
  const std::vector<std::vector<StateIndex>> blocks = partition.blocks();
  for (const std::vector<StateIndex>& members : blocks) {
    const StateIndex first = members.front();
    const ChoiceSet first_choices = choices_of(model, context, partition.block_of, first);
    for (std::size_t i = 1; i < members.size(); ++i) {
      const StateIndex other = members[i];
      if (label_of(label_class, first) != label_of(label_class, other)) {
        Violation v = pair_violation(model, partition, ViolationKind::LabelsDiffer, first, other);
        v.message += "their respected labels differ";
        return {std::move(v)};
      }
      if (first_choices.empty() &&
          alone_reward(model, context, first) != alone_reward(model, context, other)) {
        Violation v = pair_violation(model, partition, ViolationKind::RewardDiffers, first, other);
        v.message += "neither has an enabled action and their state rewards differ";
        return {std::move(v)};
      }
      if (choices_of(model, context, partition.block_of, other) != first_choices) {
        Violation v =
            pair_violation(model, partition, ViolationKind::BlockProbabilityDiffers, first, other);
        v.message +=
            "their sets of choices differ: some choice of one reaches the blocks with "
            "probabilities (or a reward) that no choice of the other has";
        return {std::move(v)};
      }
    }
  }
  return {};
}

VerificationResult check_unlabelled_coarsest(const model::ExplicitModel& model, std::size_t context,
                                             const model::Partition& partition,
                                             const std::vector<std::uint32_t>& label_class) {
  const StateIndex n = model.num_states();
  std::vector<std::uint32_t> class_of(n);
  std::size_t classes = 0;
  {
    std::map<std::pair<std::uint32_t, std::optional<Rational>>, std::uint32_t> initial;
    for (StateIndex s = 0; s < n; ++s) {
      const auto key = std::make_pair(label_of(label_class, s), alone_reward(model, context, s));
      class_of[s] =
          initial.try_emplace(key, static_cast<std::uint32_t>(initial.size())).first->second;
    }
    classes = initial.size();
  }
  for (;;) {
    std::map<std::pair<std::uint32_t, ChoiceSet>, std::uint32_t> split;
    std::vector<std::uint32_t> next(n);
    for (StateIndex s = 0; s < n; ++s) {
      auto key = std::make_pair(class_of[s], choices_of(model, context, class_of, s));
      next[s] =
          split.try_emplace(std::move(key), static_cast<std::uint32_t>(split.size())).first->second;
    }
    const std::size_t count = split.size();
    class_of = std::move(next);
    if (count == classes) break;
    classes = count;
  }
  if (classes == partition.num_blocks) return {};
  // Two blocks whose members the fixpoint puts in one class.
  std::map<std::uint32_t, BlockIndex> block_of_class;
  for (StateIndex s = 0; s < n; ++s) {
    const auto [it, inserted] = block_of_class.try_emplace(class_of[s], partition.block_of[s]);
    if (inserted || it->second == partition.block_of[s]) continue;
    Violation v;
    v.kind = ViolationKind::BlocksCouldMerge;
    v.block = it->second;
    v.other_block = partition.block_of[s];
    v.message = describe_block(model, partition, *v.block) + " and " +
                describe_block(model, partition, *v.other_block) +
                " are bisimilar under unlabelled choices: the partition is not the coarsest";
    return {std::move(v)};
  }
  return {};
}

}  // namespace oasis::verify
