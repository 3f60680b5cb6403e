#pragma once
// Checks that an input file (a spec, a PRISM program) is text we can lex: valid UTF-8, no NUL
// bytes. Binary files and files in other encodings get one clear error instead of a cascade of
// lexer errors.

#include "support/diagnostics.hpp"

namespace oasis {

[[nodiscard]] bool validate_input(FileId file, DiagnosticEngine& diagnostics);

}  // namespace oasis
