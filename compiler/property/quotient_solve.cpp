#include "property/quotient_solve.hpp"

#include <string>

#include "bisim/quotient.hpp"
#include "bisim/refinement.hpp"

namespace oasis::property {
namespace {

// Per state, the combination of the call's state sets it belongs to: states of different
// combinations are never merged.
std::vector<std::uint32_t> set_classes(const EngineCall& call, std::uint32_t n) {
  if (call.phi.empty() && call.psi.empty()) return {};
  std::vector<std::uint32_t> classes(n, 0);
  for (std::uint32_t s = 0; s < n; ++s) {
    const bool in_phi = !call.phi.empty() && call.phi[s];
    const bool in_psi = !call.psi.empty() && call.psi[s];
    classes[s] = (in_phi ? 1U : 0U) | (in_psi ? 2U : 0U);
  }
  return classes;
}

modelcheck::StateSet project(const modelcheck::StateSet& set, const model::Partition& partition) {
  if (set.empty()) return set;
  modelcheck::StateSet projected(partition.num_blocks, false);
  for (std::uint32_t s = 0; s < partition.num_states(); ++s)
    if (set[s]) projected[partition.block_of[s]] = true;
  return projected;
}

// The parts of `model` that bisimulation and the quotient read, with one context: the
// model's transitions and the call's rewards (none for a probability).
model::ExplicitModel reduced_model(const model::ExplicitModel& model, const EngineCall& call) {
  model::ExplicitModel reduced;
  reduced.name = model.name;
  reduced.type = model.type;
  reduced.states.size = model.num_states();
  reduced.states.initial = model.states.initial;
  reduced.actions = model.actions;
  reduced.values = model.values;
  model::RewardTable rewards;
  if (call.reads_rewards()) {
    rewards = *call.rewards;
  } else {
    rewards.state.assign(model.num_states(), RationalPool::kZero);
  }
  reduced.contexts.push_back({"property", model.contexts.front().transitions, std::move(rewards)});
  return reduced;
}

void lift(modelcheck::Result& result, const model::Partition& partition) {
  std::vector<modelcheck::Value> values(partition.num_states());
  for (std::uint32_t s = 0; s < partition.num_states(); ++s)
    values[s] = result.values[partition.block_of[s]];
  result.values = std::move(values);
  if (!result.scheduler) return;
  const auto lift_actions = [&](const std::vector<model::ActionIndex>& by_block) {
    std::vector<model::ActionIndex> by_state(partition.num_states());
    for (std::uint32_t s = 0; s < partition.num_states(); ++s)
      by_state[s] = by_block[partition.block_of[s]];
    return by_state;
  };
  if (!result.scheduler->action.empty())
    result.scheduler->action = lift_actions(result.scheduler->action);
  for (auto& step : result.scheduler->by_step)
    step = lift_actions(step);
}

// The chain `actions` induces: each state keeps the edges of the action it takes.
model::TransitionMatrix induced_chain(const model::TransitionMatrix& matrix,
                                      const std::vector<model::ActionIndex>& actions) {
  model::TransitionMatrix chain;
  chain.num_states = matrix.num_states;
  chain.num_actions = 1;
  chain.choice_begin.push_back(0);
  for (model::StateIndex s = 0; s < matrix.num_states; ++s) {
    const model::ActionIndex a = scheduled_action(matrix, actions, s);
    if (a < matrix.num_actions) {
      for (model::EdgeIndex e = matrix.edges_begin(s, a); e < matrix.edges_end(s, a); ++e) {
        chain.edge_target.push_back(matrix.edge_target[e]);
        chain.edge_probability.push_back(matrix.edge_probability[e]);
      }
    }
    chain.choice_begin.push_back(static_cast<model::EdgeIndex>(chain.edge_target.size()));
  }
  return chain;
}

// The rewards of the chain: each state's state reward plus that of the action it keeps.
model::RewardTable induced_rewards(const model::RewardTable& rewards,
                                   const model::TransitionMatrix& matrix,
                                   const std::vector<model::ActionIndex>& actions,
                                   RationalPool& values) {
  model::RewardTable chain;
  chain.state = rewards.state;
  if (rewards.choice.empty()) return chain;
  for (model::StateIndex s = 0; s < matrix.num_states; ++s) {
    const model::ActionIndex a = scheduled_action(matrix, actions, s);
    if (a >= matrix.num_actions) continue;
    const Rational total = values[rewards.state[s]] + values[rewards.choice[matrix.choice(s, a)]];
    chain.state[s] = values.intern(total);
  }
  return chain;
}

bool same_value(const modelcheck::Value& a, const modelcheck::Value& b, modelcheck::Mode mode) {
  if (a.infinite || b.infinite) return a.infinite == b.infinite;
  if (mode == modelcheck::Mode::kExact) return a.exact == b.exact;
  return a.lower <= b.upper && b.lower <= a.upper;
}

}  // namespace

model::ActionIndex scheduled_action(const model::TransitionMatrix& matrix,
                                    const std::vector<model::ActionIndex>& actions,
                                    model::StateIndex s) {
  const model::ActionIndex a = actions[s];
  if (a != modelcheck::Scheduler::kAnyAction && a < matrix.num_actions && matrix.enabled(s, a))
    return a;
  model::ActionIndex first = 0;
  while (first < matrix.num_actions && !matrix.enabled(s, first))
    ++first;
  return first;
}

modelcheck::Result solve_on_quotient(const model::ExplicitModel& model, const EngineCall& call,
                                     const modelcheck::Options& options, QuotientSize& size) {
  const model::ExplicitModel reduced = reduced_model(model, call);
  bisim::RefinementOptions refinement;
  refinement.label_class = set_classes(call, model.num_states());
  const model::Partition partition = bisim::coarsest_bisimulation(reduced, 0, refinement);
  const model::ExplicitModel quotient = bisim::build_quotient(reduced, 0, partition);
  EngineCall projected = call;
  projected.phi = project(call.phi, partition);
  projected.psi = project(call.psi, partition);
  const model::Context& context = quotient.contexts.front();
  modelcheck::Result result =
      run(projected, *context.transitions, quotient.values, &context.rewards, options);
  lift(result, partition);
  size = {model.num_states(), partition.num_blocks};
  result.method += "; on the bisimulation quotient, " + std::to_string(partition.num_blocks) +
                   " blocks of " + std::to_string(model.num_states()) + " states";
  return result;
}

bool scheduler_reproduces(const model::ExplicitModel& model, const EngineCall& call,
                          const modelcheck::Result& result, const modelcheck::Options& options) {
  if (!result.scheduler || result.scheduler->action.empty()) return true;
  const model::TransitionMatrix& matrix = *model.contexts.front().transitions;
  const model::TransitionMatrix chain = induced_chain(matrix, result.scheduler->action);
  RationalPool values = model.values;
  model::RewardTable rewards;
  if (call.reads_rewards())
    rewards = induced_rewards(*call.rewards, matrix, result.scheduler->action, values);
  EngineCall on_chain = call;
  on_chain.optimum = modelcheck::Optimum::kNone;
  modelcheck::Options plain = options;
  plain.want_scheduler = false;
  const modelcheck::Result again = run(on_chain, chain, values, &rewards, plain);
  for (std::size_t s = 0; s < again.values.size(); ++s)
    if (!same_value(again.values[s], result.values[s], options.mode)) return false;
  return true;
}

}  // namespace oasis::property
