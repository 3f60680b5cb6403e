// Building the reduced equations (reduced_system.hpp) and making a policy proper.

#include "modelcheck/reduced_system.hpp"

#include <deque>
#include <stdexcept>

#include "modelcheck/end_components.hpp"

namespace oasis::modelcheck {
namespace {

void number_variables(const ChoiceGraph& graph, const Reduction& reduction, ReducedSystem& system) {
  system.var_of_state.assign(graph.num_states, kNoVariable);
  std::vector<std::uint32_t> var_of_component;
  for (model::StateIndex s = 0; s < graph.num_states; ++s) {
    if (!reduction.variables[s]) continue;
    const std::uint32_t component =
        reduction.collapse.empty() ? kNoComponent : reduction.collapse[s];
    if (component == kNoComponent) {
      system.var_of_state[s] = system.num_vars++;
      continue;
    }
    if (component >= var_of_component.size()) var_of_component.resize(component + 1, kNoVariable);
    if (var_of_component[component] == kNoVariable) var_of_component[component] = system.num_vars++;
    system.var_of_state[s] = var_of_component[component];
  }
  system.first_member.assign(system.num_vars + 1, 0);
  for (model::StateIndex s = 0; s < graph.num_states; ++s) {
    if (system.var_of_state[s] != kNoVariable) ++system.first_member[system.var_of_state[s] + 1];
  }
  for (std::uint32_t v = 0; v < system.num_vars; ++v)
    system.first_member[v + 1] += system.first_member[v];
  system.members.resize(system.first_member.back());
  std::vector<std::uint32_t> next(system.first_member.begin(), system.first_member.end() - 1);
  for (model::StateIndex s = 0; s < graph.num_states; ++s) {
    if (system.var_of_state[s] != kNoVariable) system.members[next[system.var_of_state[s]]++] = s;
  }
}

bool only_returns(const ChoiceGraph& graph, const ReducedSystem& system, ChoiceId c,
                  std::uint32_t var) {
  for (std::uint32_t e = graph.first_edge[c]; e < graph.first_edge[c + 1]; ++e) {
    if (system.var_of_state[graph.target[e]] != var) return false;
  }
  return true;
}

void add_choice(const ChoiceGraph& graph, const RationalPool& values, const Reduction& reduction,
                ChoiceId c, ReducedSystem& system) {
  Rational constant = reduction.reward.empty() ? Rational(0) : reduction.reward[c];
  bool leaves = false;
  for (std::uint32_t e = graph.first_edge[c]; e < graph.first_edge[c + 1]; ++e) {
    const model::StateIndex t = graph.target[e];
    const std::uint32_t var = system.var_of_state[t];
    if (var == kNoVariable) {
      leaves = true;
      if (reduction.known_one[t]) constant += values[graph.probability[e]];
      continue;
    }
    system.edge_var.push_back(var);
    system.edge_probability.push_back(graph.probability[e]);
  }
  system.origin.push_back(c);
  system.constant.push_back(std::move(constant));
  system.leaves.push_back(leaves);
  system.first_edge.push_back(static_cast<std::uint32_t>(system.edge_var.size()));
}

}  // namespace

ReducedSystem reduce(const ChoiceGraph& graph, const RationalPool& values,
                     const Reduction& reduction) {
  ReducedSystem system;
  number_variables(graph, reduction, system);
  system.first_choice.push_back(0);
  system.first_edge.push_back(0);
  for (std::uint32_t v = 0; v < system.num_vars; ++v) {
    for (std::uint32_t m = system.first_member[v]; m < system.first_member[v + 1]; ++m) {
      const model::StateIndex s = system.members[m];
      for (ChoiceId c = graph.first_choice[s]; c < graph.first_choice[s + 1]; ++c) {
        if (!reduction.offered[c] || only_returns(graph, system, c, v)) continue;
        add_choice(graph, values, reduction, c, system);
      }
    }
    if (system.num_choices() == system.first_choice.back())
      throw std::logic_error("model checker: a state of unknown value has no choice left");
    system.first_choice.push_back(system.num_choices());
  }
  return system;
}

std::vector<std::uint32_t> make_proper(const ReducedSystem& system,
                                       std::vector<std::uint32_t> policy) {
  // Every (variable, choice) with an edge into each variable, in CSR form.
  std::vector<std::uint32_t> first_into(system.num_vars + 1, 0);
  for (const std::uint32_t t : system.edge_var)
    ++first_into[t + 1];
  for (std::uint32_t v = 0; v < system.num_vars; ++v)
    first_into[v + 1] += first_into[v];
  std::vector<std::uint32_t> into_choice(system.edge_var.size());
  std::vector<std::uint32_t> next(first_into.begin(), first_into.end() - 1);
  for (std::uint32_t c = 0; c < system.num_choices(); ++c) {
    for (std::uint32_t e = system.first_edge[c]; e < system.first_edge[c + 1]; ++e)
      into_choice[next[system.edge_var[e]]++] = c;
  }
  std::vector<std::uint32_t> var_of_choice(system.num_choices());
  for (std::uint32_t v = 0; v < system.num_vars; ++v) {
    for (std::uint32_t c = system.first_choice[v]; c < system.first_choice[v + 1]; ++c)
      var_of_choice[c] = v;
  }

  // First backwards along the policy alone from the variables whose choice leaves: those keep
  // their choice. Then, for the rest only, an attractor over all choices: a variable that
  // reaches a reached one only by another choice switches to it.
  std::vector<bool> reached(system.num_vars, false);
  std::deque<std::uint32_t> queue;
  auto reach = [&](std::uint32_t v) {
    reached[v] = true;
    queue.push_back(v);
  };
  auto spread = [&](bool may_switch) {
    while (!queue.empty()) {
      const std::uint32_t t = queue.front();
      queue.pop_front();
      for (const bool keep : {true, false}) {
        if (!keep && !may_switch) break;
        for (std::uint32_t i = first_into[t]; i < first_into[t + 1]; ++i) {
          const std::uint32_t c = into_choice[i];
          const std::uint32_t v = var_of_choice[c];
          if (reached[v] || (keep && policy[v] != c)) continue;
          policy[v] = c;
          reach(v);
        }
      }
    }
  };
  for (std::uint32_t v = 0; v < system.num_vars; ++v) {
    if (system.leaves[policy[v]]) reach(v);
  }
  spread(false);
  for (std::uint32_t v = 0; v < system.num_vars; ++v) {
    if (reached[v]) {
      queue.push_back(v);
      continue;
    }
    for (std::uint32_t c = system.first_choice[v]; c < system.first_choice[v + 1]; ++c) {
      if (!system.leaves[c]) continue;
      policy[v] = c;
      reach(v);
      break;
    }
  }
  spread(true);
  for (std::uint32_t v = 0; v < system.num_vars; ++v) {
    if (!reached[v]) throw std::logic_error("model checker: a variable cannot reach a known state");
  }
  return policy;
}

}  // namespace oasis::modelcheck
