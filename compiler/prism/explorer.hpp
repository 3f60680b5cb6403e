#pragma once
// Exploration of a checked PRISM program: the reachable states of the parallel composition of
// its modules, numbered in breadth-first order from the initial states, as the explicit model
// every algorithm reads.
//
// Semantics, as PRISM's and Storm's:
// * An unlabelled command is a choice of its own. A labelled one synchronises: action `a` is
//   enabled when every module whose commands use `a` has an enabled `a` command, and each
//   combination of such commands is a choice whose outcomes multiply.
// * In a dtmc the enabled choices of a state are taken uniformly at random: its one
//   distribution is their average, under the one action "[0]".
// * In an mdp each choice is an action. A labelled choice is named by its label; an
//   unlabelled one by its place among the state's choices, "[0]", "[1]", ..., as PRISM's
//   explicit files number them (the unlabelled choices come first). A state with several
//   choices of one label names the later ones "a[1]", "a[2]", ...
// * A state with no enabled command (a deadlock) gets a self-loop, "[0]", and the label
//   "deadlock"; the initial states have the label "init".
// * Each reward structure is a context; a program without one has the single context
//   "default" with no rewards.

#include <cstdint>
#include <functional>
#include <optional>

#include "model/explicit_model.hpp"
#include "prism/program.hpp"
#include "support/limits.hpp"

namespace oasis::prism {

struct ExploreOptions {
  std::uint32_t max_states = limits::kDefaultMaxStates;
  std::function<void(std::uint64_t found, std::uint64_t explored)> progress;
};

// nullopt after reporting an error: a state limit passed, a variable updated out of its
// range, probabilities that do not sum to 1 in some state, an evaluation error.
std::optional<model::ExplicitModel> explore(const Program& program, DiagnosticEngine& diagnostics,
                                            const ExploreOptions& options = {});

}  // namespace oasis::prism
