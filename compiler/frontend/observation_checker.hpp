#pragma once
// The catalog's observation model: how the robot's sensor reports the state, p(observed
// state | true state), and whether the reward follows the true or the observed state.

#include "frontend/ast.hpp"
#include "frontend/expression_checker.hpp"
#include "frontend/scope.hpp"
#include "model/model_ir.hpp"

namespace oasis::frontend {

// Fills ir.observation from `decl`. Needs ir.kind and, for explicit models, the states
// declared in `scope`. Reports a noise level outside [0, 1), rows that do not sum to exactly
// 1, states named twice or not at all, and models it does not support yet (continuous ones;
// a confusion matrix without named states).
void check_observation(const ast::ObservationDecl& decl, const Scope& scope, model::ModelIR& ir,
                       DiagnosticEngine& diagnostics, ExpressionChecker& expressions);

}  // namespace oasis::frontend
