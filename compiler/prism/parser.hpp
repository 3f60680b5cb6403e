#pragma once
// Parses the tokens of a PRISM program into its syntax tree. Every syntax error is reported;
// after one, the parser skips to the end of the declaration or command and goes on, so one
// run shows them all.

#include <vector>

#include "prism/ast.hpp"
#include "prism/token.hpp"

namespace oasis::prism {

ast::Program parse(const std::vector<Token>& tokens, DiagnosticEngine& diagnostics);

}  // namespace oasis::prism
