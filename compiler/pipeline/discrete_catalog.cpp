#include "pipeline/discrete_catalog.hpp"

#include <chrono>

#include "bisim/quotient.hpp"
#include "oasis/rt/catalog_validation.hpp"
#include "support/parallel.hpp"

namespace oasis::pipeline {
namespace {

static_assert(policy::kNoAction == rt::kNoAction,
              "the compiler and the runtime mark dead ends alike");

DiscreteAbstraction abstract_one(const model::ExplicitModel& model, std::size_t context,
                                 const DiscreteOptions& options) {
  DiscreteAbstraction result;
  result.context = context;
  bisim::RefinementOptions refinement;
  refinement.rounding_step = options.rounding_step;
  refinement.label_class = options.label_class;
  refinement.unlabelled_choices = options.unlabelled_choices;
  if (options.progress) {
    refinement.progress = [&options, context](const bisim::RefinementProgress& progress) {
      options.progress(context, progress);
    };
  }
  const auto start = std::chrono::steady_clock::now();
  result.partition = bisim::coarsest_bisimulation(model, context, refinement, &result.statistics);
  result.refinement_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!options.solve) return result;
  result.quotient = bisim::build_quotient(model, context, result.partition);
  result.policy = policy::solve(result.quotient, 0, options.policy);
  return result;
}

// The detection model compares an observed reward with R(s) of the block: every member must
// have the same state reward.
bool block_rewards(const model::ExplicitModel& model, std::size_t context,
                   const model::Partition& partition, std::vector<double>& out,
                   std::string& error) {
  const model::RewardTable& rewards = model.contexts[context].rewards;
  std::vector<std::optional<ValueId>> seen(partition.num_blocks);
  out.assign(partition.num_blocks, 0.0);
  for (model::StateIndex s = 0; s < model.num_states(); ++s) {
    const model::BlockIndex z = partition.block_of[s];
    const ValueId id = rewards.state[s];
    if (!seen[z]) {
      seen[z] = id;
      out[z] = to_double(model.values[id]);
    } else if (model.values[*seen[z]] != model.values[id]) {
      error = "context '" + model.contexts[context].name + "': state " + model.states.name(s) +
              " has state reward " + describe(model.values[id]) +
              " but other states of its block have " + describe(model.values[*seen[z]]) +
              "; the detection model needs one reward R(s) per abstract state";
      return false;
    }
  }
  return true;
}

std::optional<model::AbstractionData> abstraction_data(const model::ExplicitModel& model,
                                                       const DiscreteAbstraction& abstraction,
                                                       const CatalogOptions& options,
                                                       std::string& error) {
  const std::size_t context = abstraction.context;
  model::AbstractionData data;
  data.context = model.contexts[context].name;
  data.num_blocks = abstraction.partition.num_blocks;
  data.block_of = abstraction.partition.block_of;
  if (!block_rewards(model, context, abstraction.partition, data.block_reward, error))
    return std::nullopt;
  const model::ExplicitModel& quotient = abstraction.quotient;
  data.quotient = model::csr_of(quotient, *quotient.contexts[0].transitions);
  data.reward.resize(std::size_t{data.num_blocks} * model.num_actions());
  for (model::StateIndex z = 0; z < data.num_blocks; ++z) {
    for (model::ActionIndex a = 0; a < model.num_actions(); ++a)
      data.reward[std::size_t{z} * model.num_actions() + a] = to_double(quotient.reward(0, z, a));
  }
  data.policy = abstraction.policy.action;
  data.value = abstraction.policy.value;
  if (options.p_correct || model.observation.kind != model::ObservationSpec::Kind::kNone)
    data.state_transitions = model::csr_of(model, *model.contexts[context].transitions);
  return data;
}

// The robust section's observation model: --robust's symmetric one, else the spec's.
bool observation_model(const model::ExplicitModel& model, const CatalogOptions& options,
                       model::CatalogData& catalog, std::string& error) {
  const model::ObservationSpec& spec = model.observation;
  if (spec.reward_follows_observed) catalog.reward_source = rt::RewardSource::kObservedState;
  if (options.p_correct) {
    catalog.observation = rt::ObservationKind::kSymmetric;
    catalog.p_correct = *options.p_correct;
  } else if (spec.kind == model::ObservationSpec::Kind::kSymmetric) {
    catalog.observation = rt::ObservationKind::kSymmetric;
    catalog.p_correct = to_double(1 - spec.noise);
  } else if (spec.kind == model::ObservationSpec::Kind::kMatrix) {
    catalog.observation = rt::ObservationKind::kMatrix;
    for (const Rational& p : spec.confusion)
      catalog.confusion.push_back(to_double(p));
  }
  // A factored model learns that it has a single state only now.
  if (catalog.observation == rt::ObservationKind::kSymmetric && model.num_states() == 1 &&
      catalog.p_correct != 1.0) {
    error =
        "the model has a single state, so its observed state cannot be wrong: the state "
        "noise must be 0";
    return false;
  }
  return true;
}

// An imported model (docs/formats.md) has one context and no switching model: its catalog's
// is the trivial one, that context always, so the filter has nothing to switch.
bool switching_model(const model::ExplicitModel& model, model::CatalogData& catalog,
                     std::string& error) {
  const std::size_t n = model.contexts.size();
  if (model.switching.matrix.empty() && n == 1) {
    catalog.switching = {1.0};
    catalog.prior = {1.0};
    return true;
  }
  if (model.switching.matrix.size() != n * n || model.switching.prior.size() != n) {
    error = "the model has " + std::to_string(n) +
            " contexts but no switching model and prior for them";
    return false;
  }
  for (const Rational& p : model.switching.matrix)
    catalog.switching.push_back(to_double(p));
  for (const Rational& p : model.switching.prior)
    catalog.prior.push_back(to_double(p));
  return true;
}

}  // namespace

std::vector<std::size_t> all_contexts(const model::ExplicitModel& model) {
  std::vector<std::size_t> contexts(model.contexts.size());
  for (std::size_t c = 0; c < contexts.size(); ++c)
    contexts[c] = c;
  return contexts;
}

std::optional<std::vector<DiscreteAbstraction>> abstract_contexts(
    const model::ExplicitModel& model, const std::vector<std::size_t>& contexts,
    const DiscreteOptions& options, std::string& error) {
  std::vector<DiscreteAbstraction> results(contexts.size());
  parallel_for(contexts.size(), options.jobs,
               [&](std::size_t i) { results[i] = abstract_one(model, contexts[i], options); });
  for (const DiscreteAbstraction& result : results) {
    if (!options.solve || result.policy.converged) continue;
    error = "context '" + model.contexts[result.context].name +
            "': value iteration did not converge in " + std::to_string(result.policy.iterations) +
            " sweeps (last change " + std::to_string(result.policy.residual) +
            "); use a smaller discount or a horizon";
    return std::nullopt;
  }
  return results;
}

std::optional<model::CatalogData> catalog_data(const model::ExplicitModel& model,
                                               const std::vector<DiscreteAbstraction>& abstractions,
                                               std::uint64_t spec_hash,
                                               const CatalogOptions& options, std::string& error) {
  model::CatalogData catalog;
  catalog.name = model.name;
  catalog.spec_hash = spec_hash;
  catalog.compiler_version = OASIS_VERSION;
  catalog.num_states = model.num_states();
  catalog.num_actions = model.num_actions();
  catalog.action_names = model.actions;
  for (model::StateIndex s = 0; s < model.num_states(); ++s)
    catalog.state_names.push_back(model.states.name(s));
  if (!switching_model(model, catalog, error)) return std::nullopt;
  for (const DiscreteAbstraction& abstraction : abstractions) {
    auto data = abstraction_data(model, abstraction, options, error);
    if (!data) return std::nullopt;
    catalog.abstractions.push_back(std::move(*data));
  }
  if (!observation_model(model, options, catalog, error)) return std::nullopt;
  // The last line of defence: the front ends refuse every value a catalog cannot carry, so a
  // catalog that the runtime would refuse is a bug here, reported rather than written.
  std::string why;
  if (!rt::validate(catalog.view(), &why)) {
    error = "internal error: the catalog would be invalid (" + why + "); please report it";
    return std::nullopt;
  }
  return catalog;
}

std::optional<model::CatalogData> build_catalog(const model::ExplicitModel& model,
                                                std::uint64_t spec_hash,
                                                const BuildOptions& options, std::string& error) {
  if (model.num_states() == 0 || model.contexts.empty()) {
    error = "the model has no states or no contexts";
    return std::nullopt;
  }
  DiscreteOptions abstraction = options.abstraction;
  abstraction.solve = true;
  const auto abstractions = abstract_contexts(model, all_contexts(model), abstraction, error);
  if (!abstractions) return std::nullopt;
  return catalog_data(model, *abstractions, spec_hash, options.catalog, error);
}

}  // namespace oasis::pipeline
