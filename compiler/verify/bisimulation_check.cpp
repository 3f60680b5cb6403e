#include "verify/bisimulation_check.hpp"

#include <algorithm>
#include <optional>
#include <vector>

#include "verify/block_distribution.hpp"

namespace oasis::verify {
namespace {

using model::ActionIndex;
using model::StateIndex;

struct Pair {
  StateIndex first;  // the block's first member
  StateIndex other;
  model::BlockIndex block;
};

Violation pair_violation(const model::ExplicitModel& model, const model::Partition& partition,
                         ViolationKind kind, const Pair& pair, std::optional<ActionIndex> action) {
  Violation violation;
  violation.kind = kind;
  violation.state = pair.first;
  violation.other_state = pair.other;
  violation.block = pair.block;
  violation.action = action;
  violation.message = model.states.name(pair.first) + " and " + model.states.name(pair.other) +
                      " are both in " + describe_block(model, partition, pair.block) + ", but ";
  return violation;
}

// P(block | s, a) from s's sorted (block, probability) list: 0 when the block is absent.
Rational probability_of(const std::vector<std::pair<model::BlockIndex, Rational>>& distribution,
                        model::BlockIndex block) {
  for (const auto& [b, p] : distribution) {
    if (b == block) return p;
  }
  return 0;
}

// States with no enabled action have no R(s, a); their state reward R(s), the reward for
// being in s, must agree instead.
std::optional<Violation> deadlock_reward_violation(const model::ExplicitModel& model,
                                                   std::size_t context,
                                                   const model::Partition& partition,
                                                   const Pair& pair) {
  const model::TransitionMatrix& matrix = *model.contexts[context].transitions;
  for (ActionIndex a = 0; a < model.num_actions(); ++a) {
    if (matrix.enabled(pair.first, a)) return std::nullopt;
  }
  const auto& rewards = model.contexts[context].rewards.state;
  const Rational& first = model.values[rewards[pair.first]];
  const Rational& other = model.values[rewards[pair.other]];
  if (first == other) return std::nullopt;
  Violation v = pair_violation(model, partition, ViolationKind::RewardDiffers, pair, std::nullopt);
  v.message += "neither has an enabled action, and R(" + model.states.name(pair.first) +
               ") = " + describe(first) + " while R(" + model.states.name(pair.other) +
               ") = " + describe(other);
  return v;
}

// "\"one\", \"done\"" or "no label": the labels that hold in `state`.
std::string labels_text(const model::ExplicitModel& model, StateIndex state) {
  std::string text;
  for (std::uint32_t label : model.labels.of(state))
    text += (text.empty() ? "\"" : ", \"") + model.labels.names[label] + "\"";
  return text.empty() ? "no label" : text;
}

}  // namespace

VerificationResult check_bisimulation(const model::ExplicitModel& model, std::size_t context,
                                      const model::Partition& partition,
                                      const std::vector<std::uint32_t>& label_class) {
  const model::TransitionMatrix& matrix = *model.contexts[context].transitions;
  const std::vector<std::vector<StateIndex>> blocks = partition.blocks();
  const ActionIndex k = model.num_actions();

  // Enabled actions and rewards: local to each state, so checked first.
  for (model::BlockIndex b = 0; b < blocks.size(); ++b) {
    const StateIndex r = blocks[b].front();
    for (std::size_t i = 1; i < blocks[b].size(); ++i) {
      const Pair pair{r, blocks[b][i], b};
      if (!label_class.empty() && label_class[pair.first] != label_class[pair.other]) {
        Violation v =
            pair_violation(model, partition, ViolationKind::LabelsDiffer, pair, std::nullopt);
        v.message += "their respected labels differ: " + model.states.name(pair.first) + " holds " +
                     labels_text(model, pair.first) + ", " + model.states.name(pair.other) +
                     " holds " + labels_text(model, pair.other);
        return {std::move(v)};
      }
      for (ActionIndex a = 0; a < k; ++a) {
        const bool in_first = matrix.enabled(pair.first, a);
        if (in_first != matrix.enabled(pair.other, a)) {
          Violation v =
              pair_violation(model, partition, ViolationKind::EnabledActionsDiffer, pair, a);
          v.message += "action " + model.actions[a] + " is enabled in " +
                       model.states.name(in_first ? pair.first : pair.other) + " and not in " +
                       model.states.name(in_first ? pair.other : pair.first);
          return {std::move(v)};
        }
        if (!in_first) continue;
        const Rational first_reward = model.reward(context, pair.first, a);
        const Rational other_reward = model.reward(context, pair.other, a);
        if (first_reward != other_reward) {
          Violation v = pair_violation(model, partition, ViolationKind::RewardDiffers, pair, a);
          v.message += "R(" + model.states.name(pair.first) + ", " + model.actions[a] +
                       ") = " + describe(first_reward) + " and R(" + model.states.name(pair.other) +
                       ", " + model.actions[a] + ") = " + describe(other_reward);
          return {std::move(v)};
        }
      }
      if (auto v = deadlock_reward_violation(model, context, partition, pair))
        return {std::move(*v)};
    }
  }

  // Probabilities of reaching each block, compared as sorted (block, probability) lists.
  for (model::BlockIndex b = 0; b < blocks.size(); ++b) {
    if (blocks[b].size() < 2) continue;
    const StateIndex r = blocks[b].front();
    for (ActionIndex a = 0; a < k; ++a) {
      if (!matrix.enabled(r, a)) continue;
      const auto expected = block_distribution(model, context, partition.block_of, r, a);
      for (std::size_t i = 1; i < blocks[b].size(); ++i) {
        const Pair pair{r, blocks[b][i], b};
        const auto actual = block_distribution(model, context, partition.block_of, pair.other, a);
        if (actual == expected) continue;
        // The smallest block on which the two lists disagree.
        std::size_t x = 0;
        while (x < expected.size() && x < actual.size() && expected[x] == actual[x])
          ++x;
        model::BlockIndex target = 0;
        if (x == expected.size()) {
          target = actual[x].first;
        } else if (x == actual.size()) {
          target = expected[x].first;
        } else {
          target = std::min(expected[x].first, actual[x].first);
        }
        Violation v =
            pair_violation(model, partition, ViolationKind::BlockProbabilityDiffers, pair, a);
        v.other_block = target;
        v.message += "under action " + model.actions[a] + ", " + model.states.name(r) +
                     " reaches " + describe_block(model, partition, target) + " with probability " +
                     describe(probability_of(expected, target)) + " and " +
                     model.states.name(pair.other) + " with probability " +
                     describe(probability_of(actual, target));
        return {std::move(v)};
      }
    }
  }
  return {};
}

}  // namespace oasis::verify
