#pragma once
// The catalog-wide parts of a spec: the abstraction transition model p(phi_t | phi_{t-1})
// ("switching") and the prior p(phi_0).

#include <cstdint>

#include "frontend/ast.hpp"
#include "frontend/expression_checker.hpp"
#include "frontend/scope.hpp"
#include "model/model_ir.hpp"

namespace oasis::frontend {

// At least one context and at most limits::kMaxContexts; false after reporting otherwise.
bool check_context_count(const ast::CatalogDecl& catalog, DiagnosticEngine& diagnostics);

// Fills ir.switching from the catalog; `contexts` maps context names to their index in
// ir.contexts. Reports rows that do not sum to 1, unknown or missing contexts, and so on.
void check_switching_and_prior(const ast::CatalogDecl& catalog,
                               const NameTable<std::uint32_t>& contexts, model::ModelIR& ir,
                               DiagnosticEngine& diagnostics, ExpressionChecker& expressions);

// Puts the catalog's `property` items into ir.properties: each name once. Their texts are read
// by the property parser later (input/, which links it); a continuous model, whose catalog
// states no property values yet, refuses them here.
void check_properties(const ast::CatalogDecl& catalog, bool continuous, model::ModelIR& ir,
                      DiagnosticEngine& diagnostics);

}  // namespace oasis::frontend
