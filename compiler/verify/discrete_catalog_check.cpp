#include "verify/discrete_catalog_check.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "support/text.hpp"
#include "verify/number_text.hpp"
#include "verify/policy_check.hpp"
#include "verify/verifier.hpp"

namespace oasis::verify {
namespace {

// |d - q| <= 2^-50 |q| + slack, exactly.
bool carried(double d, const Rational& q, double slack = 0x1p-60) {
  if (!std::isfinite(d)) return false;
  const Rational difference = abs(Rational(d) - q);
  return difference <= abs(q) * Rational(1, 1L << 50) + Rational(slack);
}

struct Failure {
  std::string message;
};

// ---- names, switching, prior --------------------------------------------------------------

std::optional<Failure> check_names(const model::ExplicitModel& model, const rt::CatalogView& c) {
  if (c.name == nullptr || model.name != c.name)
    return Failure{"the catalog is named " + quoted(c.name ? c.name : "") + ", the model " +
                   quoted(model.name)};
  if (c.num_states != model.num_states() || c.num_actions != model.num_actions())
    return Failure{"the catalog has " + std::to_string(c.num_states) + " states and " +
                   std::to_string(c.num_actions) + " actions, the model " +
                   std::to_string(model.num_states()) + " and " +
                   std::to_string(model.num_actions())};
  for (std::uint32_t a = 0; a < c.num_actions; ++a)
    if (model.actions[a] != c.action_names[a])
      return Failure{"action " + std::to_string(a) + " is " + quoted(c.action_names[a]) +
                     " in the catalog, " + quoted(model.actions[a]) + " in the model"};
  for (std::uint32_t s = 0; c.state_names != nullptr && s < c.num_states; ++s)
    if (model.states.name(s) != c.state_names[s])
      return Failure{"state " + std::to_string(s) + " is " + quoted(c.state_names[s]) +
                     " in the catalog, " + quoted(model.states.name(s)) + " in the model"};
  if (c.num_abstractions != model.contexts.size())
    return Failure{"the catalog has " + std::to_string(c.num_abstractions) +
                   " abstractions, the model " + std::to_string(model.contexts.size()) +
                   " contexts"};
  for (std::uint32_t i = 0; i < c.num_abstractions; ++i)
    if (model.contexts[i].name != c.abstractions[i].context)
      return Failure{"abstraction " + std::to_string(i) + " is for context " +
                     quoted(c.abstractions[i].context) + ", the model's context " +
                     std::to_string(i) + " is " + quoted(model.contexts[i].name)};
  return std::nullopt;
}

std::optional<Failure> check_switching(const model::ExplicitModel& model,
                                       const rt::CatalogView& c) {
  const std::size_t n = c.num_abstractions;
  // An imported model has one context and no switching model: the trivial one.
  std::vector<Rational> matrix = model.switching.matrix;
  std::vector<Rational> prior = model.switching.prior;
  if (matrix.empty() && n == 1) {
    matrix = {Rational(1)};
    prior = {Rational(1)};
  }
  if (matrix.size() != n * n || prior.size() != n)
    return Failure{"the model's switching model does not match the catalog's size"};
  for (std::size_t k = 0; k < n * n; ++k)
    if (!carried(c.switching[k], matrix[k]))
      return Failure{"switching[" + std::to_string(k / n) + "][" + std::to_string(k % n) + "] is " +
                     number_text(c.switching[k]) + ", the model says " + describe(matrix[k])};
  for (std::size_t i = 0; i < n; ++i)
    if (!carried(c.prior[i], prior[i]))
      return Failure{"prior[" + std::to_string(i) + "] is " + number_text(c.prior[i]) +
                     ", the model says " + describe(prior[i])};
  return std::nullopt;
}

// ---- observation model ----------------------------------------------------------------------

const char* kind_text(rt::ObservationKind kind) {
  switch (kind) {
    case rt::ObservationKind::kNone:
      return "none";
    case rt::ObservationKind::kSymmetric:
      return "symmetric";
    case rt::ObservationKind::kMatrix:
      return "a confusion matrix";
  }
  return "unknown";
}

const char* source_text(rt::RewardSource source) {
  return source == rt::RewardSource::kObservedState ? "the observed state" : "the true state";
}

// The catalog's observation model against the spec's (or --robust's symmetric one), item by
// item; `summary` says what was compared when it holds.
std::optional<Failure> check_observation(const model::ExplicitModel& model,
                                         const rt::CatalogView& c,
                                         const CatalogCheckOptions& options, std::string& summary) {
  using Kind = model::ObservationSpec::Kind;
  const model::ObservationSpec& spec = model.observation;
  rt::ObservationKind expected = rt::ObservationKind::kNone;
  if (options.robust_p_correct || spec.kind == Kind::kSymmetric) {
    expected = rt::ObservationKind::kSymmetric;
  } else if (spec.kind == Kind::kMatrix) {
    expected = rt::ObservationKind::kMatrix;
  }
  const rt::ObservationModel& obs = c.observation;
  if (obs.kind != expected) {
    std::string hint;
    if (expected == rt::ObservationKind::kNone)
      hint = " (compiled with --robust P? then verify with --robust P too)";
    return Failure{std::string("the catalog's observation model is ") + kind_text(obs.kind) +
                   ", the " + (options.robust_p_correct ? "command line's" : "spec's") + " " +
                   kind_text(expected) + hint};
  }
  const rt::RewardSource source = spec.reward_follows_observed ? rt::RewardSource::kObservedState
                                                               : rt::RewardSource::kTrueState;
  if (obs.reward_source != source)
    return Failure{std::string("the catalog's reward follows ") + source_text(obs.reward_source) +
                   ", the spec's " + source_text(source)};
  if (expected == rt::ObservationKind::kNone) {
    summary = "none";
    return std::nullopt;
  }
  if (expected == rt::ObservationKind::kSymmetric) {
    const Rational p_correct =
        options.robust_p_correct ? Rational(*options.robust_p_correct) : Rational(1 - spec.noise);
    const std::string said = options.robust_p_correct
                                 ? "--robust " + number_text(*options.robust_p_correct)
                                 : "1 - noise = " + describe(p_correct);
    if (!carried(obs.p_correct, p_correct))
      return Failure{"the catalog's p_correct is " + number_text(obs.p_correct) + ", not " + said};
    summary = "symmetric, p_correct " + said;
  } else {
    const std::size_t n = model.num_states();
    if (spec.confusion.size() != n * n || obs.confusion == nullptr)
      return Failure{"the confusion matrix does not match the model's states"};
    for (std::size_t k = 0; k < n * n; ++k) {
      if (!carried(obs.confusion[k], spec.confusion[k]))
        return Failure{"confusion[" + model.states.name(static_cast<model::StateIndex>(k / n)) +
                       "][" + model.states.name(static_cast<model::StateIndex>(k % n)) + "] is " +
                       number_text(obs.confusion[k]) + ", the spec says " +
                       describe(spec.confusion[k])};
    }
    summary = "confusion matrix";
  }
  summary += std::string(", reward follows ") + source_text(source);
  return std::nullopt;
}

// ---- one abstraction ----------------------------------------------------------------------

// The quotient from the model and the catalog's partition: per block and action, the
// probability of reaching each block from the block's first state (a bisimulation makes the
// choice of state irrelevant; the partition is checked first).
struct QuotientRow {
  bool enabled = false;
  std::vector<std::pair<std::uint32_t, Rational>> to;  // sorted by block
};

std::vector<QuotientRow> quotient_of(const model::ExplicitModel& model, std::size_t context,
                                     const rt::AbstractionView& abs,
                                     std::vector<model::StateIndex>& representative) {
  const model::TransitionMatrix& matrix = *model.contexts[context].transitions;
  const std::uint32_t actions = model.num_actions();
  representative.assign(abs.num_blocks, model.num_states());
  for (model::StateIndex s = model.num_states(); s-- > 0;)
    representative[abs.block_of[s]] = s;
  std::vector<QuotientRow> rows(std::size_t{abs.num_blocks} * actions);
  for (std::uint32_t z = 0; z < abs.num_blocks; ++z) {
    const model::StateIndex s = representative[z];
    for (model::ActionIndex a = 0; a < actions; ++a) {
      QuotientRow& row = rows[std::size_t{z} * actions + a];
      row.enabled = matrix.enabled(s, a);
      for (auto e = matrix.edges_begin(s, a); e < matrix.edges_end(s, a); ++e) {
        const std::uint32_t block = abs.block_of[matrix.edge_target[e]];
        auto found = std::find_if(row.to.begin(), row.to.end(),
                                  [&](const auto& entry) { return entry.first == block; });
        if (found == row.to.end()) {
          row.to.emplace_back(block, model.values[matrix.edge_probability[e]]);
        } else {
          found->second += model.values[matrix.edge_probability[e]];
        }
      }
      std::sort(row.to.begin(), row.to.end(),
                [](const auto& x, const auto& y) { return x.first < y.first; });
    }
  }
  return rows;
}

std::optional<Failure> check_rewards(const model::ExplicitModel& model, std::size_t context,
                                     const rt::AbstractionView& abs,
                                     const std::vector<model::StateIndex>& representative,
                                     const std::vector<QuotientRow>& rows) {
  const model::RewardTable& rewards = model.contexts[context].rewards;
  for (model::StateIndex s = 0; s < model.num_states(); ++s) {
    const std::uint32_t z = abs.block_of[s];
    if (!carried(abs.block_reward[z], model.values[rewards.state[s]]))
      return Failure{"block " + std::to_string(z) + " has reward " +
                     number_text(abs.block_reward[z]) + " but its state " + model.states.name(s) +
                     " has " + describe(model.values[rewards.state[s]])};
  }
  const std::uint32_t actions = model.num_actions();
  for (std::uint32_t z = 0; z < abs.num_blocks; ++z) {
    for (model::ActionIndex a = 0; a < actions; ++a) {
      if (!rows[std::size_t{z} * actions + a].enabled) continue;
      const Rational exact = model.reward(context, representative[z], a);
      const double carried_value = abs.reward[std::size_t{z} * actions + a];
      if (!carried(carried_value, exact))
        return Failure{"R^Z(block " + std::to_string(z) + ", " + model.actions[a] + ") is " +
                       number_text(carried_value) + ", the model says " + describe(exact)};
    }
  }
  return std::nullopt;
}

std::optional<Failure> check_transitions(const model::ExplicitModel& model,
                                         const rt::AbstractionView& abs,
                                         const std::vector<QuotientRow>& rows) {
  if (abs.quotient.choice_begin == nullptr) return std::nullopt;  // optional in a catalog
  const std::uint32_t actions = model.num_actions();
  for (std::uint32_t z = 0; z < abs.num_blocks; ++z) {
    for (model::ActionIndex a = 0; a < actions; ++a) {
      const std::size_t r = std::size_t{z} * actions + a;
      std::vector<std::pair<std::uint32_t, double>> carried_row;
      for (auto e = abs.quotient.choice_begin[r]; e < abs.quotient.choice_begin[r + 1]; ++e)
        carried_row.emplace_back(abs.quotient.target[e], abs.quotient.probability[e]);
      std::sort(carried_row.begin(), carried_row.end());
      const auto& exact = rows[r].to;
      const std::string where = "block " + std::to_string(z) + " under " + model.actions[a];
      if (carried_row.size() != exact.size())
        return Failure{where + " reaches " + std::to_string(carried_row.size()) +
                       " blocks in the catalog, " + std::to_string(exact.size()) + " in the model"};
      for (std::size_t k = 0; k < exact.size(); ++k) {
        if (carried_row[k].first != exact[k].first ||
            !carried(carried_row[k].second, exact[k].second, 1e-12))
          return Failure{where + ": the catalog gives block " +
                         std::to_string(carried_row[k].first) + " probability " +
                         number_text(carried_row[k].second) + ", the model block " +
                         std::to_string(exact[k].first) + " " + describe(exact[k].second)};
      }
    }
  }
  return std::nullopt;
}

std::optional<Failure> check_state_transitions(const model::ExplicitModel& model,
                                               std::size_t context,
                                               const rt::AbstractionView& abs) {
  if (abs.state_transitions.choice_begin == nullptr) return std::nullopt;
  const model::TransitionMatrix& matrix = *model.contexts[context].transitions;
  const rt::TransitionsCsr& csr = abs.state_transitions;
  const std::size_t rows = std::size_t{model.num_states()} * model.num_actions();
  for (std::size_t r = 0; r < rows; ++r) {
    if (csr.choice_begin[r + 1] - csr.choice_begin[r] !=
        matrix.choice_begin[r + 1] - matrix.choice_begin[r])
      return Failure{"the robust section's row " + std::to_string(r) + " has another size"};
    for (auto k = 0U; k < csr.choice_begin[r + 1] - csr.choice_begin[r]; ++k) {
      const auto e = csr.choice_begin[r] + k;
      const auto m = matrix.choice_begin[r] + k;
      if (csr.target[e] != matrix.edge_target[m] ||
          !carried(csr.probability[e], model.values[matrix.edge_probability[m]]))
        return Failure{"the robust section's row " + std::to_string(r) + " differs at edge " +
                       std::to_string(k)};
    }
  }
  return std::nullopt;
}

std::optional<Failure> check_policy(const model::ExplicitModel& model, std::size_t context,
                                    const rt::AbstractionView& abs,
                                    const std::vector<model::StateIndex>& representative,
                                    const std::vector<QuotientRow>& rows, std::string& summary) {
  NumericQuotient quotient;
  quotient.blocks = abs.num_blocks;
  quotient.actions = model.num_actions();
  for (std::uint32_t z = 0; z < abs.num_blocks; ++z) {
    const model::StateIndex s = representative[z];
    quotient.state_reward.push_back(
        to_double(model.values[model.contexts[context].rewards.state[s]]));
    for (model::ActionIndex a = 0; a < model.num_actions(); ++a) {
      const QuotientRow& row = rows[std::size_t{z} * model.num_actions() + a];
      quotient.reward.push_back(to_double(model.reward(context, s, a)));
      quotient.enabled.push_back(row.enabled ? 1 : 0);
      std::vector<std::pair<std::uint32_t, double>> to;
      for (const auto& [block, p] : row.to)
        to.emplace_back(block, to_double(p));
      quotient.to.push_back(std::move(to));
    }
  }
  if (auto problem = check_policy_and_values(quotient, abs.policy, abs.value,
                                             objective_of(model.objective), summary))
    return Failure{*problem};
  return std::nullopt;
}

CatalogCheck check_abstraction(const model::ExplicitModel& model, std::size_t context,
                               const rt::AbstractionView& abs) {
  CatalogCheck check{"context " + model.contexts[context].name, "", false};
  model::Partition partition;
  partition.block_of.assign(abs.block_of, abs.block_of + model.num_states());
  partition.num_blocks = abs.num_blocks;
  const VerificationResult verdict = verify_partition(model, context, partition);
  if (!verdict.ok()) {
    check.verdict = std::string("FAILED (") + kind_name(verdict.violation->kind) +
                    "): " + verdict.violation->message;
    return check;
  }
  std::vector<model::StateIndex> representative;
  const std::vector<QuotientRow> rows = quotient_of(model, context, abs, representative);
  std::string policy_summary;
  std::optional<Failure> failure = check_rewards(model, context, abs, representative, rows);
  if (!failure) failure = check_transitions(model, abs, rows);
  if (!failure) failure = check_state_transitions(model, context, abs);
  if (!failure) failure = check_policy(model, context, abs, representative, rows, policy_summary);
  if (failure) {
    check.verdict = "FAILED: " + failure->message;
    return check;
  }
  check.ok = true;
  check.verdict = "bisimulation and coarsest (" + std::to_string(abs.num_blocks) +
                  (abs.num_blocks == 1 ? " block" : " blocks") + "); rewards" +
                  (abs.quotient.choice_begin != nullptr ? ", transitions" : "") +
                  (abs.state_transitions.choice_begin != nullptr ? ", robust section" : "") +
                  " ok; policy " + policy_summary + ", values ok";
  return check;
}

CatalogCheck item(std::string name, const std::optional<Failure>& failure) {
  return {std::move(name), failure ? "FAILED: " + failure->message : "ok", !failure};
}

}  // namespace

std::vector<CatalogCheck> check_discrete_catalog(const model::ExplicitModel& model,
                                                 const rt::CatalogView& catalog,
                                                 const CatalogCheckOptions& options) {
  std::vector<CatalogCheck> checks;
  const std::optional<Failure> names = check_names(model, catalog);
  checks.push_back(item("names", names));
  if (names) return checks;  // the rest would compare unrelated things
  checks.push_back(item("switching and prior", check_switching(model, catalog)));
  std::string observation;
  const std::optional<Failure> observation_failure =
      check_observation(model, catalog, options, observation);
  checks.push_back(item("observation model", observation_failure));
  if (!observation_failure) checks.back().verdict = observation;
  for (std::size_t c = 0; c < model.contexts.size(); ++c)
    checks.push_back(check_abstraction(model, c, catalog.abstractions[c]));
  return checks;
}

}  // namespace oasis::verify
