#pragma once
// Checks a parsed PRISM program and lowers it to a Program: every error is reported, with
// its place, before giving up (constants that are not defined, names that mean nothing,
// types that do not fit, ranges and initial values out of bounds, probabilities that do not
// sum to 1, an update of another module's variable).

#include <cstddef>
#include <optional>
#include <string>

#include "model/state_labels.hpp"
#include "prism/ast.hpp"
#include "prism/constant_overrides.hpp"
#include "prism/program.hpp"
#include "support/limits.hpp"

namespace oasis::prism {

struct CheckOptions {
  // Values for the program's constants, as on PRISM's command line: "N=4,p=0.1,fair=true".
  // They define constants the program leaves undefined, and may not redefine the others.
  std::string constants;
  // Values a spec that imports the program gives (`import "f.nm" { const N = 4; }`); those of
  // `constants` take precedence, so that the command line can vary what the spec fixes.
  std::vector<ConstantOverride> spec_constants;
  bool imported = false;  // a spec imports the program: messages say where it sets values
  std::size_t max_number_bits = limits::kDefaultMaxNumberBits;
  // The reward structures that become contexts (the names of `rewards "name"`; an unnamed
  // one is "rewardsN", N its place). None by default, as Storm builds a reward model only
  // when a property asks for it: bisimulation then respects the labels alone.
  model::LabelSelection rewards{model::LabelSelection::Kind::kNone, {}};
  // Where each of rewards.names was written, when a spec's catalog names them: an unknown one
  // is reported there. Empty: they came from --rewards.
  std::vector<SourceRange> reward_ranges;
};

// nullopt when any error was reported.
std::optional<Program> check(const ast::Program& tree, std::string name,
                             DiagnosticEngine& diagnostics, const CheckOptions& options);

}  // namespace oasis::prism
