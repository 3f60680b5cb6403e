#pragma once
// The catalog of a continuous model: one gridded abstraction per context (abstracted in
// parallel, one context per thread), the switching model and prior, and the names the
// emitters need.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "model/catalog_data.hpp"
#include "model/model_ir.hpp"
#include "pipeline/continuous_abstraction.hpp"

namespace oasis::pipeline {

struct ContinuousCatalog {
  std::string name;
  std::uint64_t spec_hash = 0;
  std::string compiler_version;
  std::vector<std::string> variable_names;  // the continuous state vector, in order
  std::vector<std::string> action_names;
  std::vector<double> switching;  // [N * N] row-major
  std::vector<double> prior;      // [N]
  std::vector<ContinuousAbstraction> abstractions;
  // The spec's observation block: the position noise and what the reward follows.
  model::PositionNoiseData position;
  rt::RewardSource reward_source = rt::RewardSource::kTrueState;
};

struct ContinuousCatalogOptions {
  ContinuousOptions abstraction;
  unsigned jobs = 0;  // threads; 0: one per hardware thread, at most one per context
};

// The IR's position noise as the catalog carries it (empty without objects).
model::PositionNoiseData position_noise(const model::ModelIR& ir);

// nullopt with `error` naming the first context that failed.
std::optional<ContinuousCatalog> build_continuous_catalog(const model::ModelIR& ir,
                                                          std::uint64_t spec_hash,
                                                          const ContinuousCatalogOptions& options,
                                                          std::string& error);

}  // namespace oasis::pipeline
