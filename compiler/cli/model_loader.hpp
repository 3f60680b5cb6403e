#pragma once
// Loading any input oasisc accepts: a .oasis spec (checked, then explored unless it has
// continuous state) or an explicit model imported from another tool (.aut, .tra).

#include <cstdint>
#include <optional>
#include <string>

#include "model/explicit_model.hpp"
#include "model/model_ir.hpp"
#include "support/diagnostics.hpp"

namespace oasis::cli {

struct LoadOptions {
  std::uint32_t max_states = 20'000'000;
  std::size_t max_spec_bytes = std::size_t{16} << 20;
  std::size_t max_model_bytes = std::size_t{8} << 30;
  bool explore = true;    // false: stop after the front end
  bool progress = false;  // report exploration progress on stderr
};

struct LoadedModel {
  std::string path;
  std::optional<model::ModelIR> ir;           // specs only
  std::optional<model::ExplicitModel> model;  // discrete specs and imports
};

// nullopt after reporting errors through `diagnostics`.
std::optional<LoadedModel> load_model(const std::string& path, SourceManager& sources,
                                      DiagnosticEngine& diagnostics, const LoadOptions& options);

}  // namespace oasis::cli
