#pragma once
// The transition matrix as the model checker reads it: per state the list of its choices, each
// with its edges, and per state the choices that lead into it (for the backward searches of the
// graph precomputation). Two of PRISM's conventions are applied here once, so that no algorithm
// has to remember them: a state with no enabled action gets a self-loop (its action is
// Scheduler::kAnyAction), and a Markov chain (Optimum::kNone) keeps only the first enabled
// action of each state.

#include <cstdint>
#include <deque>
#include <vector>

#include "model/explicit_model.hpp"
#include "modelcheck/engine.hpp"

namespace oasis::modelcheck {

using ChoiceId = std::uint32_t;
inline constexpr ChoiceId kNoChoice = UINT32_MAX;

struct ChoiceGraph {
  std::uint32_t num_states = 0;
  std::vector<ChoiceId> first_choice;         // num_states + 1: choices of s are [s, s+1)
  std::vector<model::StateIndex> owner;       // per choice, its state
  std::vector<model::ActionIndex> action;     // per choice; kAnyAction for an added self-loop
  std::vector<std::uint32_t> first_edge;      // choices + 1
  std::vector<model::StateIndex> target;      // per edge
  std::vector<ValueId> probability;           // per edge
  std::vector<std::uint32_t> first_incoming;  // num_states + 1
  std::vector<ChoiceId> incoming;             // choices with an edge into the state (once each)

  [[nodiscard]] std::uint32_t num_choices() const {
    return static_cast<std::uint32_t>(owner.size());
  }
};

ChoiceGraph make_choice_graph(const Problem& problem);

// The backward search every precomputation and the scheduler's expansion share: from the
// states in `queue`, along the choices that lead into them. A choice c of a state s not yet
// `reached` for which take(s, c) holds marks s reached, is passed to taken(s, c), and the
// search goes on from s. The start states are not marked here: `reached` holds what the
// caller counts as found already.
template <typename Take, typename Taken>
void search_backwards(const ChoiceGraph& graph, std::deque<model::StateIndex> queue,
                      std::vector<bool>& reached, Take take, Taken taken) {
  while (!queue.empty()) {
    const model::StateIndex t = queue.front();
    queue.pop_front();
    for (std::uint32_t i = graph.first_incoming[t]; i < graph.first_incoming[t + 1]; ++i) {
      const ChoiceId c = graph.incoming[i];
      const model::StateIndex s = graph.owner[c];
      if (reached[s] || !take(s, c)) continue;
      reached[s] = true;
      taken(s, c);
      queue.push_back(s);
    }
  }
}

// R(s, a) of one choice: the state reward plus, for a real action, its choice reward. Empty
// reward vectors count as zero.
Rational choice_reward(const model::TransitionMatrix& matrix, const model::RewardTable& rewards,
                       const RationalPool& values, const ChoiceGraph& graph, ChoiceId choice);

// Throws std::invalid_argument when some enabled choice has R(s, a) < 0: PRISM's reward
// operators are defined for non-negative rewards only.
void require_non_negative_rewards(const model::TransitionMatrix& matrix,
                                  const model::RewardTable& rewards, const RationalPool& values,
                                  const ChoiceGraph& graph);

}  // namespace oasis::modelcheck
