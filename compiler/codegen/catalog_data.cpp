#include "codegen/catalog_data.hpp"

#include <cstdio>

#include "bisim/quotient.hpp"
#include "bisim/refinement.hpp"
#include "oasis/rt/spec_hash.hpp"
#include "policy/value_iteration.hpp"
#include "support/mapped_file.hpp"

namespace oasis::codegen {
namespace {

static_assert(policy::kNoAction == rt::kNoAction,
              "the compiler and the runtime mark dead ends alike");

}  // namespace

CsrData csr_of(const model::ExplicitModel& model, const model::TransitionMatrix& matrix) {
  CsrData csr;
  csr.choice_begin.assign(matrix.choice_begin.begin(), matrix.choice_begin.end());
  csr.target.assign(matrix.edge_target.begin(), matrix.edge_target.end());
  csr.probability.reserve(matrix.num_edges());
  for (ValueId id : matrix.edge_probability)
    csr.probability.push_back(to_double(model.values[id]));
  return csr;
}

namespace {

// The detection model compares an observed reward with R(s) of the block: every member must
// have the same state reward.
bool block_rewards(const model::ExplicitModel& model, std::size_t context,
                   const bisim::Partition& partition, std::vector<double>& out,
                   std::string& error) {
  const model::RewardTable& rewards = model.contexts[context].rewards;
  std::vector<std::optional<ValueId>> seen(partition.num_blocks);
  out.assign(partition.num_blocks, 0.0);
  for (model::StateIndex s = 0; s < model.num_states(); ++s) {
    const bisim::BlockIndex z = partition.block_of[s];
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

std::optional<AbstractionData> build_abstraction(const model::ExplicitModel& model,
                                                 std::size_t context, const BuildOptions& options,
                                                 std::string& error) {
  AbstractionData data;
  data.context = model.contexts[context].name;
  const bisim::Partition partition = bisim::coarsest_bisimulation(model, context);
  data.num_blocks = partition.num_blocks;
  data.block_of = partition.block_of;
  if (!block_rewards(model, context, partition, data.block_reward, error)) return std::nullopt;
  const model::ExplicitModel quotient = bisim::build_quotient(model, context, partition);
  data.quotient = csr_of(quotient, *quotient.contexts[0].transitions);
  data.reward.resize(std::size_t{data.num_blocks} * model.num_actions());
  for (model::StateIndex z = 0; z < data.num_blocks; ++z) {
    for (model::ActionIndex a = 0; a < model.num_actions(); ++a) {
      data.reward[std::size_t{z} * model.num_actions() + a] = to_double(quotient.reward(0, z, a));
    }
  }
  const policy::Policy solved = policy::solve(quotient, 0, options.policy);
  if (!solved.converged) {
    error = "context '" + data.context + "': value iteration did not converge in " +
            std::to_string(solved.iterations) + " sweeps (last change " +
            std::to_string(solved.residual) + "); use a smaller discount or a horizon";
    return std::nullopt;
  }
  data.policy = solved.action;
  data.value = solved.value;
  if (options.p_correct)
    data.state_transitions = csr_of(model, *model.contexts[context].transitions);
  return data;
}

}  // namespace

rt::TransitionsCsr CsrData::view() const {
  return {choice_begin.empty() ? nullptr : choice_begin.data(),
          target.empty() ? nullptr : target.data(),
          probability.empty() ? nullptr : probability.data(),
          static_cast<std::uint32_t>(target.size())};
}

rt::CatalogView CatalogData::view() {
  action_name_pointers_.clear();
  for (const std::string& action : action_names)
    action_name_pointers_.push_back(action.c_str());
  state_name_pointers_.clear();
  for (const std::string& state : state_names)
    state_name_pointers_.push_back(state.c_str());
  abstraction_views_.clear();
  for (const AbstractionData& data : abstractions) {
    rt::AbstractionView view;
    view.context = data.context.c_str();
    view.num_blocks = data.num_blocks;
    view.block_of = data.block_of.data();
    view.block_reward = data.block_reward.data();
    view.quotient = data.quotient.view();
    view.reward = data.reward.data();
    view.policy = data.policy.data();
    view.value = data.value.data();
    view.state_transitions = data.state_transitions.view();
    if (!data.grid_axes.empty()) {
      view.block_of = nullptr;
      view.grid = {static_cast<std::uint32_t>(data.grid_axes.size()), data.grid_axes.data(),
                   data.grid_break_begin.data(), data.grid_breaks.data()};
      view.cell_block = data.cell_block.data();
      view.outside_block = data.outside_block;
      view.epsilon = data.epsilon;
    }
    abstraction_views_.push_back(view);
  }
  rt::CatalogView view;
  view.name = name.c_str();
  view.spec_hash = spec_hash;
  view.compiler_version = compiler_version.c_str();
  view.num_states = num_states;
  view.num_actions = num_actions;
  view.action_names = action_name_pointers_.data();
  view.state_names = state_names.empty() ? nullptr : state_name_pointers_.data();
  view.num_abstractions = static_cast<std::uint32_t>(abstractions.size());
  view.switching = switching.data();
  view.prior = prior.data();
  view.abstractions = abstraction_views_.data();
  view.observation.kind = observation;
  view.observation.p_correct = p_correct;
  variable_name_pointers_.clear();
  for (const std::string& variable : variable_names)
    variable_name_pointers_.push_back(variable.c_str());
  view.state_dimension = static_cast<std::uint32_t>(variable_names.size());
  view.variable_names = variable_names.empty() ? nullptr : variable_name_pointers_.data();
  return view;
}

std::optional<CatalogData> build_catalog(const model::ExplicitModel& model, std::uint64_t hash,
                                         const BuildOptions& options, std::string& error) {
  if (model.num_states() == 0 || model.contexts.empty()) {
    error = "the model has no states or no contexts";
    return std::nullopt;
  }
  CatalogData catalog;
  catalog.name = model.name;
  catalog.spec_hash = hash;
  catalog.compiler_version = OASIS_VERSION;
  catalog.num_states = model.num_states();
  catalog.num_actions = model.num_actions();
  catalog.action_names = model.actions;
  for (model::StateIndex s = 0; s < model.num_states(); ++s)
    catalog.state_names.push_back(model.states.name(s));
  if (model.switching.matrix.empty() && model.contexts.size() == 1) {
    // An imported model (docs/formats.md) has one context and no switching model: the
    // catalog's is the trivial one, that context always, so the filter has nothing to switch.
    catalog.switching = {1.0};
    catalog.prior = {1.0};
  } else if (model.switching.matrix.size() != model.contexts.size() * model.contexts.size() ||
             model.switching.prior.size() != model.contexts.size()) {
    error = "the model has " + std::to_string(model.contexts.size()) +
            " contexts but no switching model and prior for them";
    return std::nullopt;
  } else {
    for (const Rational& p : model.switching.matrix)
      catalog.switching.push_back(to_double(p));
    for (const Rational& p : model.switching.prior)
      catalog.prior.push_back(to_double(p));
  }
  for (std::size_t c = 0; c < model.contexts.size(); ++c) {
    auto abstraction = build_abstraction(model, c, options, error);
    if (!abstraction) return std::nullopt;
    catalog.abstractions.push_back(std::move(*abstraction));
  }
  if (options.p_correct) {
    catalog.observation = rt::ObservationKind::kSymmetric;
    catalog.p_correct = *options.p_correct;
  }
  // The last line of defence: the front ends refuse every value a catalog cannot carry, so a
  // catalog that the runtime would refuse is a bug here, reported rather than written.
  std::string why;
  if (!rt::validate(catalog.view(), &why)) {
    error = "internal error: the catalog would be invalid (" + why + "); please report it";
    return std::nullopt;
  }
  return catalog;
}

std::uint64_t spec_hash_of_file(const std::string& path) {
  MappedFile file;
  std::string error;
  return file.open(path, std::size_t{1} << 34, error) ? rt::spec_hash(file.text()) : 0;
}

std::string hash_text(std::uint64_t hash) {
  char text[19];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
  return text;
}

}  // namespace oasis::codegen
