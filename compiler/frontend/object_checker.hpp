#pragma once
// The objects of a continuous model's observation block: which variables the sensor measures
// together, the standard deviation sigma(d) = a + b d + c d^2 of each reading (d the object's
// distance: the norm of its variables) and the probability of detecting it.

#include "frontend/ast.hpp"
#include "frontend/expression_checker.hpp"
#include "frontend/scope.hpp"
#include "model/model_ir.hpp"

namespace oasis::frontend {

// Fills ir.observation.objects from decl.objects. Reports unknown or non-continuous
// variables, a variable in two objects, an object declared twice, a sigma(d) that is not a
// polynomial of degree at most 2 in d or is negative somewhere in the object's reach, and a
// detection probability outside (0, 1]. False when it reported an error.
bool check_objects(const ast::ObservationDecl& decl, const Scope& scope, model::ModelIR& ir,
                   DiagnosticEngine& diagnostics, ExpressionChecker& expressions);

}  // namespace oasis::frontend
