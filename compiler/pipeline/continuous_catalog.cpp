#include "pipeline/continuous_catalog.hpp"

#include "support/parallel.hpp"

namespace oasis::pipeline {

model::PositionNoiseData position_noise(const model::ModelIR& ir) {
  model::PositionNoiseData noise;
  if (ir.observation.objects.empty()) return noise;
  noise.object_of.assign(ir.continuous.size(), rt::kExactVariable);
  for (std::size_t k = 0; k < ir.observation.objects.size(); ++k) {
    const model::MeasuredObject& object = ir.observation.objects[k];
    noise.object_names.push_back(object.name);
    for (const std::uint32_t v : object.variables)
      noise.object_of[v] = static_cast<std::uint32_t>(k);
    for (const Rational& coefficient : object.sigma)
      noise.sigma.push_back(to_double(coefficient));
    noise.detection.push_back(to_double(object.detection));
  }
  return noise;
}

std::optional<ContinuousCatalog> build_continuous_catalog(const model::ModelIR& ir,
                                                          std::uint64_t spec_hash,
                                                          const ContinuousCatalogOptions& options,
                                                          std::string& error) {
  ContinuousCatalog catalog;
  catalog.name = ir.name;
  catalog.spec_hash = spec_hash;
  catalog.compiler_version = OASIS_VERSION;
  for (const model::ContinuousVariable& variable : ir.continuous)
    catalog.variable_names.push_back(variable.name);
  catalog.action_names = ir.actions;
  for (const Rational& p : ir.switching.matrix)
    catalog.switching.push_back(to_double(p));
  for (const Rational& p : ir.switching.prior)
    catalog.prior.push_back(to_double(p));
  catalog.position = position_noise(ir);
  if (ir.observation.reward_follows_observed)
    catalog.reward_source = rt::RewardSource::kObservedState;

  // Contexts are independent and read the IR only.
  const std::size_t n = ir.contexts.size();
  std::vector<std::optional<ContinuousAbstraction>> results(n);
  std::vector<std::string> errors(n);
  parallel_for(n, options.jobs, [&](std::size_t c) {
    results[c] = abstract_context(ir, c, options.abstraction, errors[c]);
  });
  for (std::size_t c = 0; c < n; ++c) {
    if (!results[c]) {
      error = errors[c];
      return std::nullopt;
    }
    catalog.abstractions.push_back(std::move(*results[c]));
  }
  return catalog;
}

}  // namespace oasis::pipeline
