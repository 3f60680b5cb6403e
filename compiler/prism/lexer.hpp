#pragma once
// Splits a PRISM program into tokens. `//` comments and white space are skipped; a character
// the language does not use is reported once per run of such characters, and lexing goes on.

#include <vector>

#include "prism/token.hpp"

namespace oasis::prism {

// The tokens of `file`, ending with one EndOfFile token.
std::vector<Token> lex(FileId file, DiagnosticEngine& diagnostics);
// The tokens of `range` of a file (a property inside a spec), placed in the whole file.
std::vector<Token> lex(SourceRange range, DiagnosticEngine& diagnostics);

}  // namespace oasis::prism
