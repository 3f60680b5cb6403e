#include "pipeline/continuous_catalog.hpp"

#include <algorithm>
#include <atomic>
#include <thread>

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

  // Contexts are independent and read the IR only: one per thread.
  const std::size_t n = ir.contexts.size();
  std::vector<std::optional<ContinuousAbstraction>> results(n);
  std::vector<std::string> errors(n);
  std::atomic<std::size_t> next{0};
  auto worker = [&] {
    for (std::size_t c = next++; c < n; c = next++)
      results[c] = abstract_context(ir, c, options.abstraction, errors[c]);
  };
  const unsigned hardware = std::max(1U, std::thread::hardware_concurrency());
  const std::size_t jobs = std::min<std::size_t>(options.jobs == 0 ? hardware : options.jobs, n);
  std::vector<std::thread> threads;
  for (std::size_t j = 1; j < jobs; ++j)
    threads.emplace_back(worker);
  worker();
  for (std::thread& thread : threads)
    thread.join();
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
