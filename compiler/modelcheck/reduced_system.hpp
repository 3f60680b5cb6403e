#pragma once
// The equations left after the graph precomputation: one variable per state whose value is
// still unknown, or per end component collapsed into one (end_components.hpp), and per
// variable the choices a scheduler may take, each as
//     value(choice) = constant + sum over edges of p * x[variable of the target].
// Edges to states of known value are folded into the constant (a reachability probability of
// 1 adds p, of 0 adds nothing; an expected reward adds R(s, a) and a target adds nothing), and
// a choice that can only return to its own variable is dropped: after the precomputation such
// a choice is never the optimum (it stays in an end component forever). Both the exact and the
// sound solvers read this one form, which is why the graph work is done once for both.

#include <cstdint>
#include <vector>

#include "modelcheck/choice_graph.hpp"

namespace oasis::modelcheck {

inline constexpr std::uint32_t kNoVariable = UINT32_MAX;

struct ReducedSystem {
  std::uint32_t num_vars = 0;
  std::vector<std::uint32_t> var_of_state;  // kNoVariable for a state of known value
  std::vector<std::uint32_t> first_member;  // num_vars + 1
  std::vector<model::StateIndex> members;   // the states of each variable
  std::vector<std::uint32_t> first_choice;  // num_vars + 1
  std::vector<ChoiceId> origin;             // per choice: the choice of the graph
  std::vector<Rational> constant;           // per choice
  std::vector<bool> leaves;                 // per choice: some edge goes to a state of known value
  std::vector<std::uint32_t> first_edge;    // choices + 1
  std::vector<std::uint32_t> edge_var;
  std::vector<ValueId> edge_probability;

  [[nodiscard]] std::uint32_t num_choices() const {
    return static_cast<std::uint32_t>(origin.size());
  }
};

struct Reduction {
  const StateSet& variables;  // states of unknown value
  // End component of each state (kNoComponent: none); its states become one variable. Empty:
  // nothing collapsed.
  const std::vector<std::uint32_t>& collapse;
  const std::vector<bool>& offered;     // per choice of the graph: the solver may take it
  const StateSet& known_one;            // states of known value whose value is 1 (others: 0)
  const std::vector<Rational>& reward;  // per choice of the graph; empty: no rewards
};

ReducedSystem reduce(const ChoiceGraph& graph, const RationalPool& values,
                     const Reduction& reduction);

// A policy of the system (one choice index per variable) under which every variable leaves
// the variables with probability 1: the policy's choices where they already lead out, and
// elsewhere the choices of an attractor towards the leaving choices (the policy solvers need a
// proper policy to start from). Throws std::logic_error when some variable cannot leave.
std::vector<std::uint32_t> make_proper(const ReducedSystem& system,
                                       std::vector<std::uint32_t> policy);

}  // namespace oasis::modelcheck
