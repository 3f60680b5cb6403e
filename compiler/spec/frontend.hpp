#pragma once
// The whole front end in one call: read a .oasis file (within the size limit), check that
// it is UTF-8 text, lex, parse and check it into the model IR.

#include <cstddef>
#include <optional>
#include <string>

#include "model/model_ir.hpp"
#include "support/diagnostics.hpp"

namespace oasis::spec {

struct FrontendOptions {
  // Specs are hand-written text; anything larger is almost certainly the wrong file.
  std::size_t max_bytes = std::size_t{16} << 20;
};

// Reads `path` into `sources` and checks it. nullopt when any error was reported.
std::optional<model::ModelIR> load_spec(const std::string& path, SourceManager& sources,
                                        DiagnosticEngine& diagnostics,
                                        const FrontendOptions& options = {});

// The same for text already in `sources` (tests, fuzzing).
std::optional<model::ModelIR> check_spec_text(FileId file, DiagnosticEngine& diagnostics);

}  // namespace oasis::spec
