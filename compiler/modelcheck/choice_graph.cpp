// The checker's view of a transition matrix (choice_graph.hpp).

#include "modelcheck/choice_graph.hpp"

#include <stdexcept>
#include <string>

namespace oasis::modelcheck {
namespace {

void add_choice(ChoiceGraph& graph, const model::TransitionMatrix& matrix, model::StateIndex s,
                model::ActionIndex a) {
  graph.owner.push_back(s);
  graph.action.push_back(a);
  for (model::EdgeIndex e = matrix.edges_begin(s, a); e < matrix.edges_end(s, a); ++e) {
    graph.target.push_back(matrix.edge_target[e]);
    graph.probability.push_back(matrix.edge_probability[e]);
  }
  graph.first_edge.push_back(static_cast<std::uint32_t>(graph.target.size()));
}

void add_self_loop(ChoiceGraph& graph, model::StateIndex s) {
  graph.owner.push_back(s);
  graph.action.push_back(Scheduler::kAnyAction);
  graph.target.push_back(s);
  graph.probability.push_back(RationalPool::kOne);
  graph.first_edge.push_back(static_cast<std::uint32_t>(graph.target.size()));
}

// Counting sort of the choices by the states they lead into; a choice with two edges into
// the same state is listed once (targets within a choice are distinct).
void index_incoming(ChoiceGraph& graph) {
  graph.first_incoming.assign(graph.num_states + 1, 0);
  for (const model::StateIndex t : graph.target)
    ++graph.first_incoming[t + 1];
  for (std::uint32_t s = 0; s < graph.num_states; ++s)
    graph.first_incoming[s + 1] += graph.first_incoming[s];
  graph.incoming.resize(graph.target.size());
  std::vector<std::uint32_t> next(graph.first_incoming.begin(), graph.first_incoming.end() - 1);
  for (ChoiceId c = 0; c < graph.num_choices(); ++c) {
    for (std::uint32_t e = graph.first_edge[c]; e < graph.first_edge[c + 1]; ++e)
      graph.incoming[next[graph.target[e]]++] = c;
  }
}

}  // namespace

ChoiceGraph make_choice_graph(const Problem& problem) {
  const model::TransitionMatrix& matrix = problem.matrix;
  ChoiceGraph graph;
  graph.num_states = matrix.num_states;
  graph.first_choice.reserve(matrix.num_states + 1);
  graph.first_edge.push_back(0);
  graph.target.reserve(matrix.num_edges());
  graph.probability.reserve(matrix.num_edges());
  for (model::StateIndex s = 0; s < matrix.num_states; ++s) {
    graph.first_choice.push_back(graph.num_choices());
    for (model::ActionIndex a = 0; a < matrix.num_actions; ++a) {
      if (!matrix.enabled(s, a)) continue;
      add_choice(graph, matrix, s, a);
      if (problem.optimum == Optimum::kNone) break;
    }
    if (graph.first_choice.back() == graph.num_choices()) add_self_loop(graph, s);
  }
  graph.first_choice.push_back(graph.num_choices());
  index_incoming(graph);
  return graph;
}

Rational choice_reward(const model::TransitionMatrix& matrix, const model::RewardTable& rewards,
                       const RationalPool& values, const ChoiceGraph& graph, ChoiceId choice) {
  const model::StateIndex s = graph.owner[choice];
  Rational reward = rewards.state.empty() ? Rational(0) : values[rewards.state[s]];
  const model::ActionIndex a = graph.action[choice];
  if (a != Scheduler::kAnyAction && !rewards.choice.empty())
    reward += values[rewards.choice[matrix.choice(s, a)]];
  return reward;
}

void require_non_negative_rewards(const model::TransitionMatrix& matrix,
                                  const model::RewardTable& rewards, const RationalPool& values,
                                  const ChoiceGraph& graph) {
  for (ChoiceId c = 0; c < graph.num_choices(); ++c) {
    if (sgn(choice_reward(matrix, rewards, values, graph, c)) < 0) {
      throw std::invalid_argument("the reward of state " + std::to_string(graph.owner[c]) +
                                  " is negative: reward operators need rewards >= 0");
    }
  }
}

}  // namespace oasis::modelcheck
