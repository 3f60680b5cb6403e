#include "property/catalog_guarantees.hpp"

#include <cmath>
#include <memory>

#include "modelcheck/outward_rounding.hpp"
#include "property/parser.hpp"
#include "support/text.hpp"

namespace oasis::property {
namespace {

// What a stated interval may be wide: the sound mode's default precision.
constexpr double kStatedPrecision = 1e-6;

// The model as context `context` sees it: its rewards first (what `R` without a name reads),
// the other contexts' after it by their names, every one under the context's transitions.
// One copy of the model serves both of a context's answers: use_transitions() switches it
// between the context's MDP and the chain its policy induces.
model::ExplicitModel context_model(const model::ExplicitModel& model, std::size_t context) {
  model::ExplicitModel seen = model;
  seen.contexts.clear();
  seen.contexts.push_back(model.contexts[context]);
  for (std::size_t c = 0; c < model.contexts.size(); ++c)
    if (c != context) seen.contexts.push_back(model.contexts[c]);
  return seen;
}

void use_transitions(model::ExplicitModel& seen,
                     const std::shared_ptr<const model::TransitionMatrix>& transitions) {
  for (model::Context& each : seen.contexts)
    each.transitions = transitions;
}

// `matrix` with only the action `action_of[s]` left in each state s (all of them where it is
// rt::kNoAction): the Markov chain a policy induces, as a model with one choice per state.
std::shared_ptr<const model::TransitionMatrix> restricted(
    const model::TransitionMatrix& matrix, const std::vector<model::ActionIndex>& action_of) {
  auto chain = std::make_shared<model::TransitionMatrix>();
  chain->num_states = matrix.num_states;
  chain->num_actions = matrix.num_actions;
  chain->choice_begin.reserve(matrix.choice_begin.size());
  chain->choice_begin.push_back(0);
  for (model::StateIndex s = 0; s < matrix.num_states; ++s) {
    for (model::ActionIndex a = 0; a < matrix.num_actions; ++a) {
      if (action_of[s] == rt::kNoAction || action_of[s] == a) {
        for (model::EdgeIndex e = matrix.edges_begin(s, a); e < matrix.edges_end(s, a); ++e) {
          chain->edge_target.push_back(matrix.edge_target[e]);
          chain->edge_probability.push_back(matrix.edge_probability[e]);
        }
      }
      chain->choice_begin.push_back(static_cast<model::EdgeIndex>(chain->edge_target.size()));
    }
  }
  return chain;
}

// Each state's action under abstraction `abstraction`'s policy: its block's.
std::vector<model::ActionIndex> policy_actions(const rt::AbstractionView& abstraction,
                                               std::uint32_t num_states) {
  std::vector<model::ActionIndex> actions(num_states);
  for (model::StateIndex s = 0; s < num_states; ++s)
    actions[s] = abstraction.policy[abstraction.block_of[s]];
  return actions;
}

// The largest double <= q and the smallest double >= q, for a rational of either sign.
std::pair<double, double> doubles_around(const Rational& q) {
  if (sgn(q) >= 0) return {modelcheck::rational_down(q), modelcheck::rational_up(q)};
  const Rational negated = -q;
  return {-modelcheck::rational_up(negated), -modelcheck::rational_down(negated)};
}

struct StatedValue {
  modelcheck::Value value;
  modelcheck::Mode mode = modelcheck::Mode::kExact;
};

// The property's value in one model, or nullopt after an error (placed in the spec).
std::optional<StatedValue> answer_one(const model::ExplicitModel& model, const Names& names,
                                      const PropertiesFile& file, bool bisimulation,
                                      DiagnosticEngine& diagnostics) {
  modelcheck::Options options;
  options.precision = kStatedPrecision;
  options.mode = model.num_states() <= modelcheck::kAutoExactStates ? modelcheck::Mode::kExact
                                                                    : modelcheck::Mode::kSound;
  options.max_number_bits = modelcheck::kAutoExactNumberBits;
  Evaluator evaluator(model, names, file, diagnostics, options);
  evaluator.allow_sound_fallback(true);
  evaluator.use_bisimulation(bisimulation);
  const Property& property = file.properties.front();
  const std::optional<Answer> answer = evaluator.answer(property);
  if (!answer) return std::nullopt;
  if (answer->kind != Answer::Kind::kNumber) {
    diagnostics.error(property.range,
                      "a catalog states a number for each property: ask for one with =? "
                      "(Pmax=? [...], R=? [...]), not a bound");
    return std::nullopt;
  }
  return StatedValue{answer->value, answer->mode};
}

// The value's rt::GuaranteeField pair and its exact fraction ("" for an interval).
void store(const StatedValue& stated, double* bounds, std::string& exact) {
  if (stated.value.infinite) {
    bounds[0] = bounds[1] = HUGE_VAL;
    exact = "infinity";
    return;
  }
  if (stated.mode == modelcheck::Mode::kExact) {
    std::tie(bounds[0], bounds[1]) = doubles_around(stated.value.exact);
    exact = to_string(stated.value.exact);
    return;
  }
  bounds[0] = stated.value.lower;
  bounds[1] = stated.value.upper;
  exact.clear();
}

// The policy's and the optimum's values of every property in context `context`: [policy,
// optimum] per property, or nullopt after errors.
std::optional<std::vector<std::pair<StatedValue, StatedValue>>> answer_context(
    const model::ExplicitModel& model, const Names& names,
    const std::vector<PropertiesFile>& properties, std::size_t context,
    const std::vector<model::ActionIndex>& actions, bool bisimulation,
    DiagnosticEngine& diagnostics) {
  const auto& own = model.contexts[context].transitions;
  const auto chain = restricted(*own, actions);
  model::ExplicitModel seen = context_model(model, context);
  std::vector<std::pair<StatedValue, StatedValue>> values;
  for (const PropertiesFile& file : properties) {
    // One error is reported once: the optimum is not tried after the policy failed.
    use_transitions(seen, chain);
    const auto under_policy = answer_one(seen, names, file, bisimulation, diagnostics);
    if (!under_policy) return std::nullopt;
    use_transitions(seen, own);
    const auto at_optimum = answer_one(seen, names, file, bisimulation, diagnostics);
    if (!at_optimum) return std::nullopt;
    values.emplace_back(*under_policy, *at_optimum);
  }
  return values;
}

// Whether the stated bounds [lower, upper] hold the recomputed value: they contain the exact
// value, or meet the recomputed interval; and they are no wider than the precision allows.
bool holds(const double* bounds, const StatedValue& recomputed, std::string& why) {
  const double lower = bounds[0];
  const double upper = bounds[1];
  if (recomputed.value.infinite) {
    if (lower == HUGE_VAL && upper == HUGE_VAL) return true;
    why = "the value is infinite";
    return false;
  }
  if (!std::isfinite(lower) || !std::isfinite(upper) || !(upper - lower <= kStatedPrecision)) {
    why = "the stated interval is not finite or wider than 1e-6";
    return false;
  }
  if (recomputed.mode == modelcheck::Mode::kExact) {
    const Rational& q = recomputed.value.exact;
    if (Rational(lower) <= q && q <= Rational(upper)) return true;
    why = "the value is " + to_string(q);
    return false;
  }
  if (lower <= recomputed.value.upper && recomputed.value.lower <= upper) return true;
  why = "the value lies in [" + std::to_string(recomputed.value.lower) + ", " +
        std::to_string(recomputed.value.upper) + "]";
  return false;
}

std::string interval_text(const double* bounds) {
  if (bounds[0] == bounds[1]) return shortest_double(bounds[0]);
  return "[" + shortest_double(bounds[0]) + ", " + shortest_double(bounds[1]) + "]";
}

// Whether the catalog states the spec's properties, by name and text, in order.
GuaranteeVerdict same_properties(const model::ExplicitModel& model,
                                 const std::vector<PropertiesFile>& properties,
                                 const rt::CatalogView& catalog) {
  GuaranteeVerdict verdict{"properties", "", false};
  if (catalog.properties.count != properties.size()) {
    verdict.verdict = "the catalog states " + std::to_string(catalog.properties.count) +
                      " properties, the spec " + std::to_string(properties.size());
    return verdict;
  }
  for (std::size_t k = 0; k < properties.size(); ++k) {
    const std::string& text = properties[k].properties.front().text;
    if (model.properties[k].name != catalog.properties.names[k] ||
        text != catalog.properties.texts[k]) {
      verdict.verdict = "property " + std::to_string(k + 1) + " is " +
                        quoted(catalog.properties.names[k]) + " = " +
                        quoted(catalog.properties.texts[k]) + " in the catalog, " +
                        quoted(model.properties[k].name) + " = " + quoted(text) + " in the spec";
      return verdict;
    }
  }
  verdict.ok = true;
  verdict.verdict = properties.empty()
                        ? "none stated, as the spec states none"
                        : "the spec's " + std::to_string(properties.size()) + ", by name and text";
  return verdict;
}

}  // namespace

std::optional<std::vector<PropertiesFile>> parse_stated_properties(
    const std::vector<model::PropertySource>& sources, DiagnosticEngine& diagnostics) {
  const std::size_t errors = diagnostics.error_count();
  std::vector<PropertiesFile> files;
  for (const model::PropertySource& source : sources) {
    PropertiesFile file = parse_range(source.text, diagnostics);
    if (diagnostics.error_count() != errors) continue;
    if (file.properties.size() != 1 || !file.constants.empty() || !file.labels.empty()) {
      diagnostics.error(source.text,
                        "a catalog property is one property, without definitions (write one "
                        "'property NAME = ...;' item each)");
      continue;
    }
    files.push_back(std::move(file));
  }
  if (diagnostics.error_count() != errors) return std::nullopt;
  return files;
}

bool state_guarantees(const model::ExplicitModel& model, const Names& names,
                      const std::vector<PropertiesFile>& properties, model::CatalogData& catalog,
                      DiagnosticEngine& diagnostics) {
  if (properties.empty()) return true;
  catalog.properties.clear();
  for (std::size_t k = 0; k < properties.size(); ++k)
    catalog.properties.push_back({model.properties[k].name, properties[k].properties.front().text});
  const rt::CatalogView view = catalog.view();
  for (std::size_t i = 0; i < catalog.abstractions.size(); ++i) {
    const auto values = answer_context(model, names, properties, i,
                                       policy_actions(view.abstractions[i], model.num_states()),
                                       /*bisimulation=*/true, diagnostics);
    if (!values) return false;
    model::AbstractionData& data = catalog.abstractions[i];
    data.guarantee.assign(properties.size() * rt::kGuaranteeFields, 0.0);
    data.guarantee_exact.assign(properties.size() * 2, "");
    for (std::size_t k = 0; k < values->size(); ++k) {
      double* bounds = data.guarantee.data() + k * rt::kGuaranteeFields;
      store((*values)[k].first, bounds + rt::kPolicyLower, data.guarantee_exact[k * 2]);
      store((*values)[k].second, bounds + rt::kOptimumLower, data.guarantee_exact[k * 2 + 1]);
    }
  }
  return true;
}

std::vector<GuaranteeVerdict> check_guarantees(const model::ExplicitModel& model,
                                               const Names& names,
                                               const std::vector<PropertiesFile>& properties,
                                               const rt::CatalogView& catalog,
                                               DiagnosticEngine& diagnostics) {
  std::vector<GuaranteeVerdict> verdicts{same_properties(model, properties, catalog)};
  if (!verdicts.front().ok || properties.empty()) return verdicts;
  for (std::uint32_t i = 0; i < catalog.num_abstractions; ++i) {
    const rt::AbstractionView& abstraction = catalog.abstractions[i];
    const auto values =
        answer_context(model, names, properties, i, policy_actions(abstraction, model.num_states()),
                       /*bisimulation=*/false, diagnostics);
    for (std::size_t k = 0; k < properties.size(); ++k) {
      GuaranteeVerdict verdict{"property " + quoted(catalog.properties.names[k]) + " in context " +
                                   quoted(abstraction.context),
                               "", false};
      if (!values) {
        verdict.verdict = "cannot be recomputed (the error above)";
        verdicts.push_back(std::move(verdict));
        continue;
      }
      const double* bounds = abstraction.guarantee + k * rt::kGuaranteeFields;
      std::string why;
      if (!holds(bounds + rt::kPolicyLower, (*values)[k].first, why)) {
        verdict.verdict = "under the policy it states " + interval_text(bounds) + ", but " + why;
      } else if (!holds(bounds + rt::kOptimumLower, (*values)[k].second, why)) {
        verdict.verdict = "at the optimum it states " + interval_text(bounds + rt::kOptimumLower) +
                          ", but " + why;
      } else {
        verdict.ok = true;
        verdict.verdict = "policy " + interval_text(bounds) + ", optimum " +
                          interval_text(bounds + rt::kOptimumLower) +
                          ", recomputed on the model's own states";
      }
      verdicts.push_back(std::move(verdict));
    }
  }
  return verdicts;
}

}  // namespace oasis::property
