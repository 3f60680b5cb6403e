#pragma once
// The coarsest bisimulation under Storm's semantics for MDPs (`--choices unlabelled`): a
// state's choices are a set of distributions, whatever their actions are called. States s and
// t are equivalent iff they hold the same respected labels and every choice a of s has a
// choice b of t with R(s, a) = R(t, b) and the same probability of reaching every block, and
// the other way round. Rewards are counted as Definition 1 counts them, R(s, a) = state reward
// plus choice reward (and a state with no enabled action by its state reward), so every
// bisimulation of Definition 1 is one of these, and where every state has at most one action
// (a Markov chain) the two coarsest ones are the same.
//
// Computed by signature refinement: each round gives every state the signature (its block,
// the set of its choices' (reward, block distribution)), and renumbers blocks by signature,
// until a round splits nothing. A round costs one pass over the edges plus hashing; the
// number of rounds is at most the number of blocks (a chain of n states needs n), which is
// what makes it slower than the labelled engine's refinement on long chains.

#include <cstddef>

#include "bisim/refinement.hpp"

namespace oasis::bisim {

// Exact only (RefinementOptions::rounding_step must be unset); `options.label_class` is respected.
Partition coarsest_unlabelled_bisimulation(const model::ExplicitModel& model, std::size_t context,
                                           const RefinementOptions& options,
                                           RefinementStatistics* statistics = nullptr);

}  // namespace oasis::bisim
