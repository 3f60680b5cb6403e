#pragma once
// The textbook coarsest bisimulation, for tests only: obviously correct, slow. Signatures
// are compared as exact rationals in ordered maps; each round recomputes every state's
// signature from scratch. The fast engine (bisim/refinement.cpp) must give the same result.

#include <cstdint>
#include <map>
#include <tuple>
#include <utility>
#include <vector>

#include "model/explicit_model.hpp"
#include "model/partition.hpp"

namespace oasis::test {

// The coarsest bisimulation of `context` (Definition 1) that refines `start` (labels, one per
// state; empty: no constraint). Rounds:
//   0. block of s = (start label, [(a, R(s, a)) for each enabled a]);
//   n. block of s = (its block, [(a, {block B -> P(B | s, a)}) for each enabled a]);
// until the number of blocks stops changing. Rewards of disabled actions are ignored; a state
// with no enabled action is compared by its state reward.
inline model::Partition naive_bisimulation(const model::ExplicitModel& model, std::size_t context,
                                           const std::vector<std::uint32_t>& start = {}) {
  const model::TransitionMatrix& matrix = *model.contexts[context].transitions;
  const std::uint32_t n = model.num_states();
  const std::uint32_t k = model.num_actions();

  using RewardKey = std::pair<std::uint32_t, std::vector<std::pair<std::uint32_t, Rational>>>;
  std::map<RewardKey, std::uint32_t> initial;
  std::vector<std::uint32_t> labels(n);
  for (model::StateIndex s = 0; s < n; ++s) {
    RewardKey key{start.empty() ? 0 : start[s], {}};
    for (model::ActionIndex a = 0; a < k; ++a) {
      if (matrix.enabled(s, a)) key.second.emplace_back(a, model.reward(context, s, a));
    }
    // No enabled action: the state reward R(s) still tells the state apart (action k
    // stands for "no action").
    if (key.second.empty())
      key.second.emplace_back(k, model.values[model.contexts[context].rewards.state[s]]);
    labels[s] = initial.try_emplace(key, static_cast<std::uint32_t>(initial.size())).first->second;
  }
  model::Partition partition = model::canonical_partition(labels);

  using ActionKey = std::pair<std::uint32_t, std::map<std::uint32_t, Rational>>;
  using Signature = std::pair<std::uint32_t, std::vector<ActionKey>>;
  while (true) {
    std::map<Signature, std::uint32_t> numbering;
    for (model::StateIndex s = 0; s < n; ++s) {
      Signature signature{partition.block_of[s], {}};
      for (model::ActionIndex a = 0; a < k; ++a) {
        if (!matrix.enabled(s, a)) continue;
        ActionKey action{a, {}};
        for (model::EdgeIndex e = matrix.edges_begin(s, a); e < matrix.edges_end(s, a); ++e) {
          action.second[partition.block_of[matrix.edge_target[e]]] +=
              model.values[matrix.edge_probability[e]];
        }
        signature.second.push_back(std::move(action));
      }
      labels[s] = numbering.try_emplace(signature, static_cast<std::uint32_t>(numbering.size()))
                      .first->second;
    }
    model::Partition next = model::canonical_partition(labels);
    // The old block is part of the signature, so rounds only split: same count, same blocks.
    if (next.num_blocks == partition.num_blocks) return next;
    partition = std::move(next);
  }
}

}  // namespace oasis::test
