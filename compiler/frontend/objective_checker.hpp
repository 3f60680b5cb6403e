#pragma once
// What the policies maximise: `discount d;` or `horizon n;`, in an `mdp` block or an `import`.

#include <optional>

#include "frontend/ast.hpp"
#include "frontend/expression_checker.hpp"
#include "model/model_ir.hpp"

namespace oasis::frontend {

// Fills ir.objective and ir.objective_range (left as they are when neither is given). Refuses
// both at once, a discount outside (0, 1], discount 1 without a horizon, a discount that rounds
// to 1 as a double, and a horizon outside [1, 10^9].
void check_objective(const std::optional<ast::Setting>& discount,
                     const std::optional<ast::Setting>& horizon, model::ModelIR& ir,
                     DiagnosticEngine& diagnostics, ExpressionChecker& expressions);

}  // namespace oasis::frontend
