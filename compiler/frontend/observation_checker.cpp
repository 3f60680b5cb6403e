#include "frontend/observation_checker.hpp"

#include <optional>
#include <string>
#include <vector>

#include "frontend/object_checker.hpp"
#include "support/text.hpp"

namespace oasis::frontend {
namespace {

using model::ObservationSpec;

std::optional<std::uint32_t> state_index(const ast::Name& name, const Scope& scope,
                                         DiagnosticEngine& diagnostics) {
  const auto* entry = scope.find(name.text);
  if (entry == nullptr || entry->value.kind != SymbolKind::State) {
    diagnostics.error(name.range, entry == nullptr
                                      ? "unknown state " + quoted(name.text)
                                      : std::string(describe(entry->value.kind)) + " " +
                                            quoted(name.text) + " is not a state");
    return std::nullopt;
  }
  return entry->value.index;
}

// One row of the confusion matrix: a distribution over observed states that sums to exactly
// 1. Returns false after reporting a problem.
bool confusion_row(const ast::Distribution& distribution, const Scope& scope,
                   std::vector<Rational>& row, DiagnosticEngine& diagnostics,
                   ExpressionChecker& expressions) {
  Rational sum = 0;
  bool ok = true;
  for (const ast::Branch& branch : distribution.branches) {
    const auto observed = state_index(*branch.target, scope, diagnostics);
    const std::optional<Rational> probability = expressions.branch_probability(branch);
    if (!probability) {
      ok = false;
      continue;
    }
    const Rational& p = *probability;
    if (!observed) {
      ok = false;
      continue;
    }
    row[*observed] += p;
    sum += p;
  }
  if (ok && sum != 1) {
    diagnostics.error(distribution.range, "probabilities sum to " + describe(sum) + ", not 1");
    ok = false;
  }
  return ok;
}

bool symmetric(const ast::ObservationDecl& decl, const model::ModelIR& ir,
               ObservationSpec& observation, DiagnosticEngine& diagnostics,
               ExpressionChecker& expressions) {
  auto noise = expressions.constant_number(*decl.noise, "the state noise");
  if (!noise) return false;
  if (*noise < 0 || *noise >= 1) {
    diagnostics.error(decl.noise->range,
                      "state noise is the probability that the observed state is wrong: it must "
                      "be in [0, 1), not " +
                          describe(*noise));
    return false;
  }
  if (ir.kind == model::ModelKind::Explicit && ir.state_names.size() == 1 && *noise != 0) {
    diagnostics.error(decl.noise->range,
                      "with a single state the observed state cannot be wrong: the state noise "
                      "must be 0");
    return false;
  }
  observation.kind = ObservationSpec::Kind::kSymmetric;
  observation.noise = *noise;
  return true;
}

bool matrix(const ast::ObservationDecl& decl, const Scope& scope, const model::ModelIR& ir,
            ObservationSpec& observation, DiagnosticEngine& diagnostics,
            ExpressionChecker& expressions) {
  if (ir.kind != model::ModelKind::Explicit) {
    diagnostics.error(*decl.confusion,
                      "a confusion matrix names states, so it needs an explicit model "
                      "('states ...'); write 'state noise p;' for this model");
    return false;
  }
  const std::size_t n = ir.state_names.size();
  std::vector<Rational> confusion(n * n);
  std::vector<const ast::Name*> given(n, nullptr);
  bool ok = true;
  for (const auto& [from, distribution] : decl.rows) {
    const auto state = state_index(from, scope, diagnostics);
    if (!state) {
      ok = false;
      continue;
    }
    if (given[*state] != nullptr) {
      diagnostics.error(from.range, "state " + quoted(from.text) + " already has a row");
      diagnostics.note(given[*state]->range, "first row here");
      ok = false;
      continue;
    }
    given[*state] = &from;
    std::vector<Rational> row(n);
    if (!confusion_row(distribution, scope, row, diagnostics, expressions)) {
      ok = false;
      continue;
    }
    for (std::size_t o = 0; o < n; ++o)
      confusion[*state * n + o] = row[o];
  }
  for (std::size_t s = 0; s < n; ++s) {
    if (given[s] != nullptr) continue;
    diagnostics.error(*decl.confusion,
                      "the confusion matrix has no row for state " + quoted(ir.state_names[s]));
    ok = false;
  }
  if (!ok) return false;
  observation.kind = ObservationSpec::Kind::kMatrix;
  observation.confusion = std::move(confusion);
  return true;
}

// A continuous model's sensor: objects only.
void continuous_observation(const ast::ObservationDecl& decl, const Scope& scope,
                            model::ModelIR& ir, DiagnosticEngine& diagnostics,
                            ExpressionChecker& expressions) {
  if (decl.noise || decl.confusion) {
    diagnostics.error(decl.noise ? decl.noise->range : *decl.confusion,
                      "a continuous model's sensor is described per object: 'object NAME (x, y) "
                      "{ noise a + b * d + c * d * d; detection p; }'");
  }
  if (decl.objects.empty()) {
    diagnostics.error(decl.keyword,
                      "the observation model has no objects: add 'object NAME (x, y) { noise "
                      "sigma; }' for the variables the sensor measures");
    return;
  }
  check_objects(decl, scope, ir, diagnostics, expressions);
}

}  // namespace

void check_observation(const ast::ObservationDecl& decl, const Scope& scope, model::ModelIR& ir,
                       DiagnosticEngine& diagnostics, ExpressionChecker& expressions) {
  const bool follows_observed = decl.reward_follows && decl.reward_follows->text == "observed";
  if (ir.kind == model::ModelKind::Continuous) {
    continuous_observation(decl, scope, ir, diagnostics, expressions);
    ir.observation.reward_follows_observed = follows_observed;
    return;
  }
  if (!decl.objects.empty()) {
    diagnostics.error(decl.objects.front().range,
                      "objects measure continuous variables; a discrete model's sensor is "
                      "'state noise p;' or 'state confusion { ... }'");
    return;
  }
  if (!decl.noise && !decl.confusion) {
    diagnostics.error(decl.keyword,
                      "the observation model has no state model: add 'state noise p;' or "
                      "'state confusion { ... }'");
    return;
  }
  ObservationSpec observation;
  const bool ok = decl.noise ? symmetric(decl, ir, observation, diagnostics, expressions)
                             : matrix(decl, scope, ir, observation, diagnostics, expressions);
  if (!ok) return;
  observation.reward_follows_observed = follows_observed;
  ir.observation = std::move(observation);
}

}  // namespace oasis::frontend
