#pragma once
// A catalog built on a PRISM program: the spec's `import "robot.nm" { ... }` gives the
// program and its constants, and each of the catalog's contexts takes one of the program's
// reward structures (`context fast = rewards "time";`) over the program's one transition
// function. The switching model, prior, observation model and objective are the spec's
// (docs/spec-language.md, "Catalogs on PRISM programs").

#include <optional>
#include <string>

#include "model/explicit_model.hpp"
#include "model/model_ir.hpp"
#include "prism/load_program.hpp"
#include "support/diagnostics.hpp"

namespace oasis::prism {

// Where the spec at `spec_path` finds the file it imports as `imported`: relative to the
// spec's folder, as an #include is, unless absolute.
std::string imported_program_path(const std::string& spec_path, const std::string& imported);

// Reads, checks and explores the program `ir` imports (ir.imported must be set) and builds
// the spec's catalog on it. `options` carries the limits and --const; its rewards and spec
// fields are filled here from the spec. nullopt when any error was reported: in the spec (an
// unknown reward structure, a constant the program does not have) or in the program.
std::optional<model::ExplicitModel> load_imported_catalog(const model::ModelIR& ir,
                                                          const std::string& spec_path,
                                                          SourceManager& sources,
                                                          DiagnosticEngine& diagnostics,
                                                          LoadOptions options);

}  // namespace oasis::prism
