// Expanding a policy of collapsed end components into a scheduler (scheduler_expansion.hpp).

#include "modelcheck/scheduler_expansion.hpp"

namespace oasis::modelcheck {
namespace {

// Backwards from the exit state over the component's internal choices.
void steer_to_exit(const ChoiceGraph& graph, const ReducedSystem& system, std::uint32_t var,
                   model::StateIndex exit, const std::vector<bool>& internal, Scheduler& scheduler,
                   std::vector<bool>& assigned) {
  search_backwards(
      graph, {exit}, assigned,
      [&](model::StateIndex s, ChoiceId c) {
        return system.var_of_state[s] == var && !internal.empty() && internal[c];
      },
      [&](model::StateIndex s, ChoiceId c) { scheduler.action[s] = graph.action[c]; });
}

}  // namespace

Scheduler expand_policy(const ChoiceGraph& graph, const ReducedSystem& system,
                        const std::vector<std::uint32_t>& policy,
                        const std::vector<ChoiceId>& witness, const std::vector<bool>& internal) {
  Scheduler scheduler;
  scheduler.action.assign(graph.num_states, Scheduler::kAnyAction);
  std::vector<bool> assigned(graph.num_states, false);
  for (model::StateIndex s = 0; s < graph.num_states; ++s) {
    if (system.var_of_state[s] == kNoVariable && !witness.empty() && witness[s] != kNoChoice)
      scheduler.action[s] = graph.action[witness[s]];
  }
  for (std::uint32_t v = 0; v < system.num_vars; ++v) {
    const ChoiceId chosen = system.origin[policy[v]];
    const model::StateIndex exit = graph.owner[chosen];
    scheduler.action[exit] = graph.action[chosen];
    assigned[exit] = true;
    if (system.first_member[v + 1] - system.first_member[v] > 1)
      steer_to_exit(graph, system, v, exit, internal, scheduler, assigned);
  }
  return scheduler;
}

}  // namespace oasis::modelcheck
