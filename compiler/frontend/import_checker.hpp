#pragma once
// A spec whose model is a PRISM program: `import "robot.nm" { const N = 4; discount 0.9; }`
// in place of the `mdp` block, and a catalog whose contexts name the program's reward
// structures (`context fast = rewards "time";`). The program itself is read by the PRISM
// front end, a layer above this one (prism/imported_catalog.hpp); this checks what the spec
// says about it.

#include <optional>

#include "frontend/ast.hpp"
#include "model/model_ir.hpp"
#include "support/diagnostics.hpp"

namespace oasis::frontend {

// The IR of such a spec: ir.imported set, one context per catalog context (or one named
// "default" without rewards), the switching model, prior, observation model and objective.
// nullopt when any error was reported. `spec.imports` must not be empty.
std::optional<model::ModelIR> check_import_spec(const ast::SpecFile& spec,
                                                DiagnosticEngine& diagnostics,
                                                std::size_t max_number_bits);

}  // namespace oasis::frontend
