#pragma once
// Loading any input oasisc accepts: a .oasis spec (checked, then explored unless it has
// continuous state), a PRISM program (.pm, .nm, .prism: checked and explored) or an explicit
// model imported from another tool (.aut, .tra).

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "model/explicit_model.hpp"
#include "model/expression.hpp"
#include "model/model_ir.hpp"
#include "property/property.hpp"
#include "support/diagnostics.hpp"
#include "support/limits.hpp"

namespace oasis::input {

struct LoadOptions {
  std::uint32_t max_states = limits::kDefaultMaxStates;
  // The command's memory budget in bytes (0: none), for refusing a model file whose header
  // declares more than reading it could fit (formats::ReadOptions::memory_budget).
  std::uint64_t memory_budget = 0;
  std::size_t max_spec_bytes = limits::kDefaultMaxSpecBytes;
  std::size_t max_input_bytes = limits::kDefaultMaxInputBytes;  // .aut, .tra, CSV, JSON
  std::size_t max_number_bits = limits::kDefaultMaxNumberBits;
  bool explore = true;    // false: stop after the front end
  bool progress = false;  // report exploration progress on stderr
  // Called now and then during exploration instead (found, explored); it may throw to stop the
  // load (the Python module's Ctrl-C). Unused when `progress` is true.
  std::function<void(std::uint64_t found, std::uint64_t explored)> on_progress;
  std::string constants;  // PRISM programs: values of undefined constants (--const N=4,p=0.1)
  std::string rewards = "none";  // PRISM programs: reward structures as contexts (--rewards)
  bool hash_source = true;       // false: leave source_hash 0 (a command that writes no catalog)
};

struct LoadedModel {
  std::string path;
  std::optional<model::ModelIR> ir;           // .oasis specs that write their model
  std::optional<model::ExplicitModel> model;  // discrete specs, PRISM programs and imports
  bool prism_program = false;                 // a PRISM program, given or imported by the spec
  // A PRISM program, given directly or imported by a spec: its constants, formulas and
  // variables, which properties may read (prism::Program::names).
  std::vector<std::pair<std::string, model::Expression>> names;
  // A spec's stated properties (`property NAME = ...;`), parsed, one file each, in the model's
  // order (property/catalog_guarantees.hpp answers them).
  std::vector<property::PropertiesFile> properties;
  // rt::spec_hash of the bytes the front end or the reader parsed, read once: a catalog
  // remembers which spec it was compiled from by it. 0 when LoadOptions::hash_source is false.
  std::uint64_t source_hash = 0;
};

// nullopt after reporting errors through `diagnostics`.
std::optional<LoadedModel> load_model(const std::string& path, SourceManager& sources,
                                      DiagnosticEngine& diagnostics, const LoadOptions& options);

}  // namespace oasis::input
