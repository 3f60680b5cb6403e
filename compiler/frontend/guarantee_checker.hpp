#pragma once
// Continuous models with guarantees (docs/guarantees.md): the `input` declarations, the
// `objective` with its safe and target sets, and the `grid` it is solved on; and the rule that
// dynamics which are not affine (or read an input) need such an objective, since the catalog
// path abstracts affine dynamics only.

#include "frontend/ast.hpp"
#include "frontend/expression_checker.hpp"
#include "frontend/scope.hpp"
#include "model/model_ir.hpp"

namespace oasis::frontend {

// Declares each `input` in `scope` (so that dynamics can read it) and fills ir.inputs. Runs
// after the constants and the continuous variables are declared, before any body.
void declare_inputs(const ast::MdpDecl& mdp, model::ModelIR& ir, Scope& scope,
                    ExpressionChecker& expressions, DiagnosticEngine& diagnostics);

// Fills ir.guarantee and ir.grid_cells, and refuses what does not fit together: an objective
// on a discrete model, with a catalog or without a grid; nonlinear dynamics without an
// objective; a map that cannot be enclosed on the domain (a divisor that can reach 0, the log
// of a range that reaches 0, ...). Runs after the contexts are built.
void check_guarantee(const ast::SpecFile& spec, const ast::MdpDecl& mdp, model::ModelIR& ir,
                     const Scope& scope, ExpressionChecker& expressions,
                     DiagnosticEngine& diagnostics);

}  // namespace oasis::frontend
