#pragma once
// Recursive-descent parser for .oasis specs (grammar: docs/spec-language.md).
// It reports every syntax error it can: after an error it skips to the end of the statement
// (`;` or `}`) and goes on. Expressions nested deeper than kMaxNesting are refused with an
// error, never a stack overflow.

#include <vector>

#include "frontend/ast.hpp"
#include "frontend/token.hpp"
#include "support/diagnostics.hpp"
#include "support/limits.hpp"

namespace oasis::frontend {

inline constexpr int kMaxNesting = limits::kMaxNesting;

ast::SpecFile parse(FileId file, const std::vector<Token>& tokens, DiagnosticEngine& diagnostics);

}  // namespace oasis::frontend
