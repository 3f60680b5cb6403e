#pragma once
// Parses PRISM properties: a `.props`/`.pctl` file, or the text of `--prop`. Properties follow
// one another, each optionally named (`"elected": P=? [F "elected"]`) and optionally ended by
// `;`; `//` comments as in programs. Every syntax error is reported with its place; after one
// the parser skips to the next `;` and goes on.

#include <vector>

#include "prism/token.hpp"
#include "property/property.hpp"

namespace oasis::property {

PropertiesFile parse(const std::vector<prism::Token>& tokens, DiagnosticEngine& diagnostics);

// Lexes and parses `file` (which must be text: input validation is the caller's).
PropertiesFile parse_file(FileId file, DiagnosticEngine& diagnostics);
// Lexes and parses `range` of a file: a spec's `property NAME = TEXT;` (its TEXT), errors placed
// in the spec.
PropertiesFile parse_range(SourceRange range, DiagnosticEngine& diagnostics);

}  // namespace oasis::property
