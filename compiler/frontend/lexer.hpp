#pragma once
// Turns the text of a spec into tokens. Comments are `// ...` and `/* ... */`.
// The input has already passed validate_input() (UTF-8, no NUL bytes).

#include <string_view>
#include <vector>

#include "frontend/token.hpp"
#include "support/diagnostics.hpp"

namespace oasis::frontend {

// Lexes the whole file; always ends with an EndOfFile token. Bad characters are reported
// and become Invalid tokens so that parsing can go on and report more.
std::vector<Token> lex(FileId file, DiagnosticEngine& diagnostics);

// True when `text` lexes as one identifier: a letter or '_', then letters, digits and '_', and
// not a keyword. For names that programs write into spec fragments (oasisc fit), so that a
// fragment never carries text the spec language would read as something else.
[[nodiscard]] bool is_identifier(std::string_view text);

}  // namespace oasis::frontend
