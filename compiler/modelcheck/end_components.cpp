// Maximal end components by repeated SCC decomposition (end_components.hpp).

#include "modelcheck/end_components.hpp"

#include "modelcheck/strongly_connected.hpp"

namespace oasis::modelcheck {
namespace {

Digraph alive_graph(const ChoiceGraph& graph, const std::vector<bool>& alive_choice) {
  Digraph digraph;
  digraph.first.assign(graph.num_states + 1, 0);
  for (model::StateIndex s = 0; s < graph.num_states; ++s) {
    for (ChoiceId c = graph.first_choice[s]; c < graph.first_choice[s + 1]; ++c) {
      if (!alive_choice[c]) continue;
      for (std::uint32_t e = graph.first_edge[c]; e < graph.first_edge[c + 1]; ++e)
        digraph.next.push_back(graph.target[e]);
    }
    digraph.first[s + 1] = static_cast<std::uint32_t>(digraph.next.size());
  }
  return digraph;
}

// Drops the choices that may leave their state's component (or reach a dropped state), then
// the states left without a choice. Returns whether anything was dropped.
bool drop_leaving(const ChoiceGraph& graph, const Components& components, StateSet& alive_state,
                  std::vector<bool>& alive_choice) {
  bool changed = false;
  for (model::StateIndex s = 0; s < graph.num_states; ++s) {
    if (!alive_state[s]) continue;
    bool any_left = false;
    for (ChoiceId c = graph.first_choice[s]; c < graph.first_choice[s + 1]; ++c) {
      if (!alive_choice[c]) continue;
      for (std::uint32_t e = graph.first_edge[c]; e < graph.first_edge[c + 1]; ++e) {
        const model::StateIndex t = graph.target[e];
        if (!alive_state[t] || components.of_node[t] != components.of_node[s]) {
          alive_choice[c] = false;
          changed = true;
          break;
        }
      }
      any_left = any_left || alive_choice[c];
    }
    if (!any_left) {
      alive_state[s] = false;
      changed = true;
    }
  }
  return changed;
}

}  // namespace

EndComponents maximal_end_components(const ChoiceGraph& graph, const StateSet& states,
                                     const std::vector<bool>& allowed) {
  StateSet alive_state = states;
  std::vector<bool> alive_choice(graph.num_choices());
  for (ChoiceId c = 0; c < graph.num_choices(); ++c)
    alive_choice[c] = allowed[c] && states[graph.owner[c]];
  Components components;
  do {
    components = strongly_connected_components(alive_graph(graph, alive_choice));
  } while (drop_leaving(graph, components, alive_state, alive_choice));

  EndComponents result;
  result.of_state.assign(graph.num_states, kNoComponent);
  std::vector<std::uint32_t> renumbered(components.count, kNoComponent);
  for (model::StateIndex s = 0; s < graph.num_states; ++s) {
    if (!alive_state[s]) continue;
    std::uint32_t& id = renumbered[components.of_node[s]];
    if (id == kNoComponent) id = result.count++;
    result.of_state[s] = id;
  }
  result.internal = std::move(alive_choice);
  return result;
}

}  // namespace oasis::modelcheck
