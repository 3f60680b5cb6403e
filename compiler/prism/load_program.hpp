#pragma once
// The PRISM front end in one call: read a PRISM program (.pm, .nm, .prism), check that it is
// text, lex, parse and check it, and explore it into the explicit model, with valuations as
// state names, PRISM's labels as atomic propositions and each reward structure as a context.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "model/explicit_model.hpp"
#include "prism/constant_overrides.hpp"
#include "prism/explorer.hpp"
#include "support/diagnostics.hpp"

namespace oasis::prism {

struct LoadOptions {
  std::string constants;  // --const N=4,p=0.1
  // A spec that imports the program: its constants, where it names each reward structure, and
  // where it names the file (a file that cannot be read is reported there).
  std::vector<ConstantOverride> spec_constants;
  std::vector<SourceRange> reward_ranges;
  std::optional<SourceRange> imported_at;
  // --rewards: the reward structures that become contexts (CheckOptions::rewards).
  model::LabelSelection rewards{model::LabelSelection::Kind::kNone, {}};
  std::size_t max_bytes = limits::kDefaultMaxSpecBytes;
  std::size_t max_number_bits = limits::kDefaultMaxNumberBits;
  ExploreOptions explore;
  // When set, receives the checked program's names (Program::names), for the properties.
  std::vector<std::pair<std::string, model::Expression>>* names = nullptr;
};

// Whether `path` names a PRISM program by its extension.
bool is_program_path(const std::string& path);

// nullopt when any error was reported.
std::optional<model::ExplicitModel> load_program(const std::string& path, SourceManager& sources,
                                                 DiagnosticEngine& diagnostics,
                                                 const LoadOptions& options);

// The same for text already in `sources` (tests, fuzzing); `name` names the model.
std::optional<model::ExplicitModel> load_program_text(FileId file, const std::string& name,
                                                      DiagnosticEngine& diagnostics,
                                                      const LoadOptions& options);

}  // namespace oasis::prism
