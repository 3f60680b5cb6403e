#pragma once
// Exploration: from the model IR to the explicit model every algorithm reads.
// Explicit models keep every declared state, in declaration order. Factored models get the
// states reachable from the initial state under any context's commands, numbered in
// breadth-first order, which makes the numbering deterministic.

#include <cstdint>
#include <functional>
#include <optional>

#include "model/explicit_model.hpp"
#include "model/model_ir.hpp"
#include "support/diagnostics.hpp"
#include "support/limits.hpp"

namespace oasis::model {

struct ExploreOptions {
  std::uint32_t max_states = limits::kDefaultMaxStates;
  // Called now and then with the number of states found and explored so far.
  std::function<void(std::uint64_t found, std::uint64_t explored)> progress;
};

// nullopt after reporting an error: a state limit passed, a variable sent out of its range,
// two commands of one action enabled in the same state (not an MDP), an action with no
// enabled command where the spec asks for none to be missing, a bad probability. A spec that
// imports a PRISM program (ir.imported) is refused: prism::load_imported_catalog explores it.
std::optional<ExplicitModel> explore(const ModelIR& ir, DiagnosticEngine& diagnostics,
                                     const ExploreOptions& options = {});

}  // namespace oasis::model
