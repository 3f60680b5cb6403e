#pragma once
// Turns the text of a spec into tokens. Comments are `// ...` and `/* ... */`.
// The input has already passed validate_input() (UTF-8, no NUL bytes).

#include <vector>

#include "frontend/token.hpp"
#include "support/diagnostics.hpp"

namespace oasis::frontend {

// Lexes the whole file; always ends with an EndOfFile token. Bad characters are reported
// and become Invalid tokens so that parsing can go on and report more.
std::vector<Token> lex(FileId file, DiagnosticEngine& diagnostics);

}  // namespace oasis::frontend
