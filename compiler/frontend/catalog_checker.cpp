#include "frontend/catalog_checker.hpp"

#include <string>
#include <vector>

#include "support/double_range.hpp"
#include "support/limits.hpp"
#include "support/text.hpp"

namespace oasis::frontend {
namespace {

// A distribution over contexts, e.g. `0.8: a + 0.2: b`, as one row of N probabilities.
// Returns false after reporting a problem.
bool context_distribution(const ast::Distribution& distribution,
                          const NameTable<std::uint32_t>& contexts, std::vector<Rational>& row,
                          DiagnosticEngine& diagnostics, ExpressionChecker& expressions) {
  Rational sum = 0;
  bool ok = true;
  for (const ast::Branch& branch : distribution.branches) {
    const auto* entry = contexts.find(branch.target->text);
    if (entry == nullptr) {
      diagnostics.error(branch.target->range, "unknown context " + quoted(branch.target->text));
      ok = false;
      continue;
    }
    const std::optional<Rational> probability = expressions.branch_probability(branch);
    if (!probability) {
      ok = false;
      continue;
    }
    const Rational& p = *probability;
    row[entry->value] += p;
    sum += p;
  }
  if (ok && sum != 1) {
    diagnostics.error(distribution.range, "probabilities sum to " + describe(sum) + ", not 1");
    ok = false;
  }
  return ok;
}

void stay_matrix(const ast::SwitchingDecl& decl, model::ModelIR& ir, DiagnosticEngine& diagnostics,
                 ExpressionChecker& expressions) {
  const std::size_t n = ir.contexts.size();
  auto stay = expressions.constant_number(*decl.stay, "the probability of staying");
  if (!stay) return;
  if (*stay < 0 || *stay > 1) {
    diagnostics.error(decl.stay->range,
                      "probability of staying must be in [0, 1], not " + describe(*stay));
    return;
  }
  if (n == 1 && *stay != 1) {
    diagnostics.error(decl.stay->range, "with a single context the probability of staying is 1");
    return;
  }
  // Stay with probability p, otherwise move to one of the other N-1 contexts uniformly.
  const Rational move = n > 1 ? (1 - *stay) / Rational(static_cast<long>(n - 1)) : Rational(0);
  if (!check_carried_value(move, "the probability of moving to each other context",
                           decl.stay->range, diagnostics)) {
    return;
  }
  ir.switching.matrix.assign(n * n, move);
  for (std::size_t i = 0; i < n; ++i)
    ir.switching.matrix[i * n + i] = *stay;
}

void matrix_rows(const ast::SwitchingDecl& decl, const NameTable<std::uint32_t>& contexts,
                 model::ModelIR& ir, DiagnosticEngine& diagnostics,
                 ExpressionChecker& expressions) {
  const std::size_t n = ir.contexts.size();
  ir.switching.matrix.assign(n * n, 0);
  std::vector<const ast::Name*> given(n, nullptr);
  for (const auto& [from, distribution] : decl.rows) {
    const auto* entry = contexts.find(from.text);
    if (entry == nullptr) {
      diagnostics.error(from.range, "unknown context " + quoted(from.text));
      continue;
    }
    if (given[entry->value] != nullptr) {
      diagnostics.error(from.range, "context " + quoted(from.text) + " already has a row");
      diagnostics.note(given[entry->value]->range, "first row here");
      continue;
    }
    given[entry->value] = &from;
    std::vector<Rational> row(n);
    if (context_distribution(distribution, contexts, row, diagnostics, expressions)) {
      for (std::size_t j = 0; j < n; ++j)
        ir.switching.matrix[entry->value * n + j] = row[j];
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (given[i] == nullptr) {
      diagnostics.error(decl.range,
                        "switching model has no row for context " + quoted(ir.contexts[i].name));
    }
  }
}

}  // namespace

void check_switching_and_prior(const ast::CatalogDecl& catalog,
                               const NameTable<std::uint32_t>& contexts, model::ModelIR& ir,
                               DiagnosticEngine& diagnostics, ExpressionChecker& expressions) {
  const std::size_t n = ir.contexts.size();
  if (!catalog.switching) {
    if (n > 1) {
      diagnostics.error(catalog.range, "catalog has " + std::to_string(n) +
                                           " contexts but no switching model (add e.g. "
                                           "'switching stay 0.8;')");
    } else {
      ir.switching.matrix = {Rational(1)};
    }
  } else if (catalog.switching->stay) {
    stay_matrix(*catalog.switching, ir, diagnostics, expressions);
  } else {
    matrix_rows(*catalog.switching, contexts, ir, diagnostics, expressions);
  }

  if (!catalog.prior || catalog.prior->uniform) {
    ir.switching.prior.assign(n, Rational(1, static_cast<long>(n)));
    for (Rational& p : ir.switching.prior)
      p.canonicalize();
    return;
  }
  std::vector<Rational> prior(n);
  if (context_distribution(catalog.prior->distribution, contexts, prior, diagnostics,
                           expressions)) {
    ir.switching.prior = std::move(prior);
  }
}

void check_properties(const ast::CatalogDecl& catalog, bool continuous, model::ModelIR& ir,
                      DiagnosticEngine& diagnostics) {
  NameTable<std::uint32_t> names;
  for (const ast::PropertyDecl& decl : catalog.properties) {
    if (continuous) {
      diagnostics.error(decl.name.range,
                        "properties are stated for discrete models: a continuous catalog's "
                        "policies act on cells, whose bounds on the true system are not "
                        "computed yet");
      return;
    }
    const auto index = static_cast<std::uint32_t>(ir.properties.size());
    if (!names.declare(decl.name.text, decl.name.range, index, "property", diagnostics)) continue;
    ir.properties.push_back({std::string(decl.name.text), decl.name.range, decl.text});
  }
}

bool check_context_count(const ast::CatalogDecl& catalog, DiagnosticEngine& diagnostics) {
  if (catalog.contexts.empty()) {
    diagnostics.error(catalog.range, "catalog is empty: declare at least one 'context'");
    return false;
  }
  if (catalog.contexts.size() > limits::kMaxContexts) {
    diagnostics.error(catalog.contexts[limits::kMaxContexts].range,
                      "catalog has more than " + std::to_string(limits::kMaxContexts) +
                          " contexts (the switching model alone would need N^2 entries)");
    return false;
  }
  return true;
}

}  // namespace oasis::frontend
