// Prob0 and Prob1 in their MDP forms (graph_precomputation.hpp), as backward searches over the
// choices that lead into each state.

#include "modelcheck/graph_precomputation.hpp"

#include <cstddef>
#include <deque>

namespace oasis::modelcheck {
namespace {

// True when every successor of `choice` is in `set`.
bool all_successors_in(const ChoiceGraph& graph, ChoiceId choice, const StateSet& set) {
  for (std::uint32_t e = graph.first_edge[choice]; e < graph.first_edge[choice + 1]; ++e) {
    if (!set[graph.target[e]]) return false;
  }
  return true;
}

std::deque<model::StateIndex> members(const StateSet& set) {
  std::deque<model::StateIndex> queue;
  for (model::StateIndex s = 0; s < set.size(); ++s) {
    if (set[s]) queue.push_back(s);
  }
  return queue;
}

}  // namespace

StateSet complement(const StateSet& set) {
  StateSet result(set.size());
  for (std::size_t s = 0; s < set.size(); ++s)
    result[s] = !set[s];
  return result;
}

StateSet intersection(const StateSet& a, const StateSet& b) {
  StateSet result(a.size());
  for (std::size_t s = 0; s < a.size(); ++s)
    result[s] = a[s] && b[s];
  return result;
}

StateSet minus(const StateSet& a, const StateSet& b) {
  return intersection(a, complement(b));
}

WitnessedSet can_reach(const ChoiceGraph& graph, const StateSet& through, const StateSet& goal) {
  WitnessedSet result{goal, std::vector<ChoiceId>(graph.num_states, kNoChoice)};
  search_backwards(
      graph, members(goal), result.states,
      [&](model::StateIndex s, ChoiceId) { return through[s]; },
      [&](model::StateIndex s, ChoiceId c) { result.witness[s] = c; });
  return result;
}

StateSet prob0a(const ChoiceGraph& graph, const StateSet& phi, const StateSet& psi) {
  return complement(can_reach(graph, phi, psi).states);
}

WitnessedSet prob0e(const ChoiceGraph& graph, const StateSet& phi, const StateSet& psi) {
  // The least fixed point R = psi + {phi states all of whose choices have a successor in R}
  // is where every scheduler has a positive probability; Prob0E is its complement. A choice
  // is "hit" once one of its successors is in R; a state joins R when all its choices are.
  StateSet in_r = psi;
  std::vector<bool> hit(graph.num_choices(), false);
  std::vector<std::uint32_t> unhit(graph.num_states);
  for (model::StateIndex s = 0; s < graph.num_states; ++s)
    unhit[s] = graph.first_choice[s + 1] - graph.first_choice[s];
  std::deque<model::StateIndex> queue = members(psi);
  while (!queue.empty()) {
    const model::StateIndex t = queue.front();
    queue.pop_front();
    for (std::uint32_t i = graph.first_incoming[t]; i < graph.first_incoming[t + 1]; ++i) {
      const ChoiceId c = graph.incoming[i];
      const model::StateIndex s = graph.owner[c];
      if (hit[c] || in_r[s] || !phi[s]) continue;
      hit[c] = true;
      if (--unhit[s] == 0) {
        in_r[s] = true;
        queue.push_back(s);
      }
    }
  }
  WitnessedSet result{complement(in_r), std::vector<ChoiceId>(graph.num_states, kNoChoice)};
  for (model::StateIndex s = 0; s < graph.num_states; ++s) {
    if (!result.states[s] || !phi[s]) continue;
    for (ChoiceId c = graph.first_choice[s]; c < graph.first_choice[s + 1]; ++c) {
      if (!hit[c]) {
        result.witness[s] = c;
        break;
      }
    }
  }
  return result;
}

StateSet prob1a(const ChoiceGraph& graph, const StateSet& phi, const StateSet& psi,
                const StateSet& prob0e) {
  return complement(can_reach(graph, minus(phi, psi), prob0e).states);
}

WitnessedSet prob1e(const ChoiceGraph& graph, const StateSet& phi, const StateSet& psi) {
  // Outer greatest fixed point over R (states that may still have Pmax = 1), inner least
  // fixed point: the states that reach psi by choices that never leave R.
  StateSet outer(graph.num_states, true);
  for (;;) {
    std::vector<bool> stays(graph.num_choices());
    for (ChoiceId c = 0; c < graph.num_choices(); ++c)
      stays[c] = all_successors_in(graph, c, outer);
    WitnessedSet inner{psi, std::vector<ChoiceId>(graph.num_states, kNoChoice)};
    search_backwards(
        graph, members(psi), inner.states,
        [&](model::StateIndex s, ChoiceId c) { return phi[s] && stays[c]; },
        [&](model::StateIndex s, ChoiceId c) { inner.witness[s] = c; });
    if (inner.states == outer) return inner;
    outer = inner.states;
  }
}

}  // namespace oasis::modelcheck
