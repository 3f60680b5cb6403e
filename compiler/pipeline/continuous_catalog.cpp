#include "pipeline/continuous_catalog.hpp"

#include "support/parallel.hpp"

namespace oasis::pipeline {

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
