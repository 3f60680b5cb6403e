#pragma once
// The states whose reachability probability is 0 or 1, found on the graph alone, before any
// number is computed: Baier and Katoen, Principles of Model Checking (MIT Press 2008), 10.1.1
// and 10.6.1; Forejt, Kwiatkowska, Norman and Parker, "Automated Verification Techniques for
// Probabilistic Systems" (SFM 2011), Algorithms 1 to 4 (Prob0A, Prob0E, Prob1A, Prob1E).
// Besides making the numeric work smaller, they make the fixed point the solvers look for
// unique: without them, interval iteration's upper bound would not converge and policy
// iteration could stop at a wrong fixed point.
//
// "phi U psi" throughout; a Markov chain's Prob0 and Prob1 are the MDP forms on a graph with
// one choice per state. Each search is linear in the edges (Prob1E: per round of its outer
// fixed point).

#include <vector>

#include "modelcheck/choice_graph.hpp"

namespace oasis::modelcheck {

// A state set and, per state, a choice that proves its membership (kNoChoice where no choice
// is needed): what the schedulers of the precomputed states are made of.
struct WitnessedSet {
  StateSet states;
  std::vector<ChoiceId> witness;
};

// States from which some scheduler reaches `goal` with positive probability through states
// of `through`. Witness of a `through` state: a choice with an edge one step closer to goal.
WitnessedSet can_reach(const ChoiceGraph& graph, const StateSet& through, const StateSet& goal);

// Prob0A: Pmax(phi U psi) = 0 (every scheduler misses psi); Prob0 for a Markov chain.
StateSet prob0a(const ChoiceGraph& graph, const StateSet& phi, const StateSet& psi);

// Prob0E: Pmin(phi U psi) = 0. Witness of a phi-and-not-psi state: a choice all of whose
// successors stay in the set, so that the scheduler that takes it never reaches psi.
WitnessedSet prob0e(const ChoiceGraph& graph, const StateSet& phi, const StateSet& psi);

// Prob1A: Pmin(phi U psi) = 1, given `prob0e` (Prob1 for a Markov chain, given its Prob0):
// the states from which no scheduler reaches a probability-0 state through phi-and-not-psi
// states. Its complement, with the witnesses of can_reach, is how a scheduler misses psi.
StateSet prob1a(const ChoiceGraph& graph, const StateSet& phi, const StateSet& psi,
                const StateSet& prob0e);

// Prob1E: Pmax(phi U psi) = 1, by the nested fixed point. Witness of a phi-and-not-psi state:
// a choice that stays in the set and has an edge one layer closer to psi, so that the
// witnesses together reach psi with probability 1 (the attractor, not merely a choice that
// keeps the value 1 by staying).
WitnessedSet prob1e(const ChoiceGraph& graph, const StateSet& phi, const StateSet& psi);

StateSet complement(const StateSet& set);
StateSet intersection(const StateSet& a, const StateSet& b);
StateSet minus(const StateSet& a, const StateSet& b);

}  // namespace oasis::modelcheck
