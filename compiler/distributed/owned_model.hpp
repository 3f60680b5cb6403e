#pragma once
// One rank's share of an MDP: the choices of the states it owns. State s is owned by rank
// s mod P and is the rank's local state s div P, so shares differ by at most one state and a
// state's owner is known without a table. Ids of actions and values are global: every rank
// holds the same action list and value pool, built from all ranks' (small) tables, so that
// numbers in signatures mean the same on every rank.

#include <cstdint>
#include <string>
#include <vector>

#include "model/explicit_model.hpp"

namespace oasis::distributed {

struct Ownership {
  std::uint32_t rank = 0;
  std::uint32_t ranks = 1;

  [[nodiscard]] std::uint32_t owner(model::StateIndex s) const { return s % ranks; }
  [[nodiscard]] std::uint32_t local(model::StateIndex s) const { return s / ranks; }
  [[nodiscard]] model::StateIndex global(std::uint32_t local, std::uint32_t owner) const {
    return local * ranks + owner;
  }
  // How many states of `num_states` the rank `owner` has.
  [[nodiscard]] std::uint32_t share(std::uint32_t num_states, std::uint32_t owner) const {
    return num_states / ranks + (owner < num_states % ranks ? 1 : 0);
  }
};

struct OwnedModel {
  std::string name;  // the file's stem, as the sequential reader names the model
  Ownership ownership;
  std::uint32_t num_states = 0;  // of the whole model
  std::uint64_t num_edges = 0;   // of the whole model
  std::vector<model::StateIndex> initial;
  std::vector<std::string> actions;  // in order of first appearance in the file

  RationalPool values;  // the same ids on every rank

  // The owned states' choices: local state i has choices [state_choice_begin[i],
  // state_choice_begin[i + 1]), sorted by action; choice c has the edges
  // [edge_begin[c], edge_begin[c] + edge_count[c]), its targets ascending and distinct.
  std::vector<std::uint32_t> state_choice_begin;
  std::vector<model::ActionIndex> choice_action;
  std::vector<ValueId> choice_reward;
  std::vector<std::uint32_t> edge_begin;
  std::vector<std::uint32_t> edge_count;
  // Global state ids; refine_distributed renumbers them (to its own slots, and at the end to
  // the blocks of the targets).
  std::vector<model::StateIndex> edge_target;
  std::vector<ValueId> edge_probability;

  [[nodiscard]] std::uint32_t num_owned() const {
    return static_cast<std::uint32_t>(state_choice_begin.size() - 1);
  }
};

}  // namespace oasis::distributed
