#pragma once
// Maximal end components (Baier and Katoen, Principles of Model Checking, Algorithm 47; Forejt
// et al., SFM 2011, section 3.3): the largest sets of states a scheduler can keep the run in
// forever, each with the choices that do so. Inside one, Pmax is the same in every state and a
// scheduler may wander without progress; the solvers collapse each into one variable so that
// the fixed point they compute is the right one (and, for expected rewards, the same for the
// zero-reward end components of Rmin).
//
// The algorithm refines strongly connected components: drop every choice that may leave its
// component, then every state left without a choice, and repeat until nothing changes. Each
// round is linear; there are at most as many rounds as states, in practice a few.

#include <cstdint>
#include <vector>

#include "modelcheck/choice_graph.hpp"

namespace oasis::modelcheck {

inline constexpr std::uint32_t kNoComponent = UINT32_MAX;

struct EndComponents {
  std::vector<std::uint32_t> of_state;  // kNoComponent for a state in none
  std::uint32_t count = 0;
  std::vector<bool> internal;  // per choice: it keeps the run inside its state's component
};

// The maximal end components of the sub-MDP of `states` whose choices are those with
// allowed[c] and every successor in `states`.
EndComponents maximal_end_components(const ChoiceGraph& graph, const StateSet& states,
                                     const std::vector<bool>& allowed);

}  // namespace oasis::modelcheck
