#pragma once
// Semantic checks: turns a parsed spec into the typed model IR, reporting every problem it
// finds (unknown or duplicate names, type errors, probabilities that are negative, over 1
// or do not sum to exactly 1, missing transitions, empty contexts or catalogs, ...).

#include <optional>

#include "frontend/ast.hpp"
#include "model/model_ir.hpp"
#include "support/diagnostics.hpp"
#include "support/limits.hpp"

namespace oasis::frontend {

// nullopt when any error was reported. No number the spec writes or folds may have a numerator
// or denominator longer than `max_number_bits`.
std::optional<model::ModelIR> check(const ast::SpecFile& spec, DiagnosticEngine& diagnostics,
                                    std::size_t max_number_bits = limits::kDefaultMaxNumberBits);

}  // namespace oasis::frontend
