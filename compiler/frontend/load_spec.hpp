#pragma once
// The whole front end in one call: read a .oasis file (within the size limit), check that
// it is UTF-8 text, lex, parse and check it into the model IR.

#include <cstddef>
#include <optional>
#include <string>

#include "model/model_ir.hpp"
#include "support/diagnostics.hpp"
#include "support/limits.hpp"

namespace oasis::frontend {

struct FrontendOptions {
  // Specs are hand-written text; anything larger is almost certainly the wrong file.
  std::size_t max_bytes = limits::kDefaultMaxSpecBytes;
  // Bits of the numerator or denominator of any number the spec holds or folds.
  std::size_t max_number_bits = limits::kDefaultMaxNumberBits;
};

// Reads `path` into `sources` and checks it. nullopt when any error was reported.
std::optional<model::ModelIR> load_spec(const std::string& path, SourceManager& sources,
                                        DiagnosticEngine& diagnostics,
                                        const FrontendOptions& options = {});

// The same for text already in `sources` (tests, fuzzing).
std::optional<model::ModelIR> check_spec_text(FileId file, DiagnosticEngine& diagnostics,
                                              const FrontendOptions& options = {});

}  // namespace oasis::frontend
