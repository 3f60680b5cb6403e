// The unbounded operators of engine.hpp: `until` and `reachability_reward`. Each classifies the
// states by graph precomputation (graph_precomputation.hpp), collapses the end components the
// optimum needs collapsed (end_components.hpp), and hands the states of unknown value to the
// exact solver (exact_solver.hpp) or to interval iteration (interval_iteration.hpp).
//
// Which sets, after Forejt et al. (SFM 2011), sections 3.3 to 3.5, and PRISM:
//   P(phi U psi), chain:  0 on Prob0, 1 on Prob1.
//   Pmax:                 0 on Prob0A, 1 on Prob1E; maximal end components of the rest
//                         collapsed (their states share Pmax, and a choice that only stays
//                         would otherwise be a second fixed point).
//   Pmin:                 0 on Prob0E, 1 on Prob1A; the rest holds no end component (one
//                         would be in Prob0E).
//   R(F target), chain:   infinite off Prob1(F target).
//   Rmin:                 infinite off Prob1E(F target); only the choices that stay in
//                         Prob1E are offered; zero-reward end components collapsed.
//   Rmax:                 infinite off Prob1A(F target); the rest holds no end component.

#include <algorithm>
#include <string>
#include <utility>

#include "modelcheck/end_components.hpp"
#include "modelcheck/engine.hpp"
#include "modelcheck/exact_solver.hpp"
#include "modelcheck/graph_precomputation.hpp"
#include "modelcheck/interval_iteration.hpp"
#include "modelcheck/outward_rounding.hpp"
#include "modelcheck/scheduler_expansion.hpp"

namespace oasis::modelcheck {
namespace {

// What the precomputation found, and how the rest is to be solved.
struct Classified {
  StateSet variables;                   // unknown value
  StateSet known_one;                   // value 1 (probabilities)
  StateSet infinite;                    // value +infinity (rewards)
  std::vector<ChoiceId> witness;        // scheduler of the states of known value
  std::vector<std::uint32_t> collapse;  // end component of each state, or empty
  std::vector<bool> internal;           // per choice: moves inside its end component
  std::vector<bool> offered;            // per choice: a solver may take it
  std::vector<Rational> reward;         // per choice, or empty
  std::string sets;                     // the precomputation, for Result::method
};

void collapse_end_components(const ChoiceGraph& graph, const std::vector<bool>& allowed,
                             Classified& classified) {
  EndComponents components = maximal_end_components(graph, classified.variables, allowed);
  classified.collapse = std::move(components.of_state);
  classified.internal = std::move(components.internal);
}

Classified classify_until(const ChoiceGraph& graph, Optimum optimum, const StateSet& phi,
                          const StateSet& psi) {
  Classified classified;
  classified.offered.assign(graph.num_choices(), true);
  StateSet no;
  switch (optimum) {
    case Optimum::kNone:
      no = prob0a(graph, phi, psi);
      classified.known_one = prob1a(graph, phi, psi, no);
      classified.sets = "Prob0/Prob1";
      break;
    case Optimum::kMax: {
      no = prob0a(graph, phi, psi);
      WitnessedSet yes = prob1e(graph, phi, psi);
      classified.known_one = std::move(yes.states);
      classified.witness = std::move(yes.witness);
      classified.sets = "Prob0A/Prob1E, maximal end components collapsed";
      break;
    }
    case Optimum::kMin: {
      WitnessedSet zero = prob0e(graph, phi, psi);
      classified.known_one = prob1a(graph, phi, psi, zero.states);
      no = std::move(zero.states);
      classified.witness = std::move(zero.witness);
      classified.sets = "Prob0E/Prob1A";
      break;
    }
  }
  classified.variables = minus(complement(no), classified.known_one);
  if (optimum == Optimum::kMax) collapse_end_components(graph, classified.offered, classified);
  return classified;
}

Classified classify_reward(const ChoiceGraph& graph, Optimum optimum, const StateSet& target,
                           std::vector<Rational> reward) {
  const StateSet all(graph.num_states, true);
  Classified classified;
  classified.known_one.assign(graph.num_states, false);
  classified.offered.assign(graph.num_choices(), true);
  classified.reward = std::move(reward);
  StateSet finite;
  switch (optimum) {
    case Optimum::kNone:
      finite = prob1a(graph, all, target, prob0a(graph, all, target));
      classified.sets = "Prob0/Prob1";
      break;
    case Optimum::kMin: {
      finite = prob1e(graph, all, target).states;
      classified.sets = "Prob1E, zero-reward end components collapsed";
      break;
    }
    case Optimum::kMax: {
      WitnessedSet zero = prob0e(graph, all, target);
      finite = prob1a(graph, all, target, zero.states);
      // Where the reward is infinite, the optimal scheduler misses the target: towards Prob0E,
      // then inside it.
      classified.witness = can_reach(graph, complement(target), zero.states).witness;
      for (model::StateIndex s = 0; s < graph.num_states; ++s) {
        if (zero.states[s]) classified.witness[s] = zero.witness[s];
      }
      classified.sets = "Prob0E/Prob1A";
      break;
    }
  }
  classified.infinite = complement(finite);
  classified.variables = minus(finite, target);
  if (optimum == Optimum::kMin) {
    std::vector<bool> zero_reward(graph.num_choices());
    for (ChoiceId c = 0; c < graph.num_choices(); ++c) {
      for (std::uint32_t e = graph.first_edge[c]; e < graph.first_edge[c + 1]; ++e)
        classified.offered[c] = classified.offered[c] && finite[graph.target[e]];
      zero_reward[c] = classified.offered[c] && sgn(classified.reward[c]) == 0;
    }
    collapse_end_components(graph, zero_reward, classified);
  }
  return classified;
}

struct Solved {
  std::vector<Value> var_values;
  std::vector<std::uint32_t> policy;
  std::string method;
};

Solved solve_exact_mode(const ReducedSystem& system, const RationalPool& values, Optimum optimum,
                        const Options& options) {
  ExactSolution exact = solve_exactly(system, values, optimum, options);
  Solved solved;
  for (Rational& value : exact.values) {
    const double nearest = to_double(value);
    solved.var_values.push_back({false, std::move(value), nearest, nearest});
  }
  solved.policy = std::move(exact.policy);
  solved.method = optimum == Optimum::kNone
                      ? "state elimination over GMP rationals"
                      : "policy iteration (" + std::to_string(exact.evaluations) +
                            (exact.evaluations == 1 ? " exact policy evaluation"
                                                    : " exact policy evaluations") +
                            " by state elimination over GMP rationals)";
  return solved;
}

// The upper start of the interval iteration: 1 for probabilities; for rewards r_max times an
// inductive bound on the expected steps, over all policies (chain, Rmax) or under one proper
// policy (Rmin, whose optimum is at most that policy's value).
std::vector<double> upper_start(const ReducedSystem& system, const RationalPool& values,
                                const RoundedSystem& rounded, Optimum optimum, bool rewards,
                                const Options& options) {
  if (!rewards) return std::vector<double>(system.num_vars, 1.0);
  const double max_reward =
      rounded.constant_high.empty()
          ? 0.0
          : *std::max_element(rounded.constant_high.begin(), rounded.constant_high.end());
  if (max_reward == 0) return std::vector<double>(system.num_vars, 0.0);
  std::vector<std::uint32_t> proper;
  if (optimum == Optimum::kMin) proper = approximate_policy(system, values, optimum, 1000);
  std::vector<double> bound =
      expected_steps_bound(system, rounded, optimum == Optimum::kMin ? &proper : nullptr, options);
  for (double& b : bound)
    b = multiply_up(b, max_reward);
  return bound;
}

Solved solve_sound_mode(const ReducedSystem& system, const RationalPool& values, Optimum optimum,
                        bool rewards, const Options& options) {
  const RoundedSystem rounded = round_outward(system, values);
  IntervalSolution interval =
      interval_iteration(system, rounded, optimum,
                         upper_start(system, values, rounded, optimum, rewards, options), options);
  Solved solved;
  for (std::uint32_t v = 0; v < system.num_vars; ++v)
    solved.var_values.push_back({false, Rational(0), interval.lower[v], interval.upper[v]});
  if (options.want_scheduler && optimum != Optimum::kNone)
    solved.policy = make_proper(system, greedy_policy(system, rounded, optimum, interval));
  solved.method =
      "interval iteration (Haddad and Monmege; Baier et al., CAV 2017) with outward "
      "rounding, " +
      std::to_string(interval.sweeps) + (interval.sweeps == 1 ? " sweep" : " sweeps");
  if (rewards) {
    solved.method += ", upper start r_max * T with T an inductive bound on the expected steps";
  }
  return solved;
}

Result solve(const Problem& problem, const ChoiceGraph& graph, const Classified& classified,
             bool rewards, const Options& options) {
  const ReducedSystem system =
      reduce(graph, problem.values,
             {classified.variables, classified.collapse, classified.offered, classified.known_one,
              classified.reward});
  Solved solved = options.mode == Mode::kExact
                      ? solve_exact_mode(system, problem.values, problem.optimum, options)
                      : solve_sound_mode(system, problem.values, problem.optimum, rewards, options);
  Result result;
  result.values.resize(graph.num_states);
  for (model::StateIndex s = 0; s < graph.num_states; ++s) {
    Value& value = result.values[s];
    if (system.var_of_state[s] != kNoVariable) {
      value = solved.var_values[system.var_of_state[s]];
    } else if (!classified.infinite.empty() && classified.infinite[s]) {
      value.infinite = true;
    } else if (classified.known_one[s]) {
      value.exact = 1;
      value.lower = value.upper = 1;
    }
  }
  if (options.want_scheduler && problem.optimum != Optimum::kNone) {
    result.scheduler =
        expand_policy(graph, system, solved.policy, classified.witness, classified.internal);
  }
  result.method = (options.mode == Mode::kExact ? "exact: " : "sound: ") + classified.sets +
                  ", then " + solved.method;
  return result;
}

}  // namespace

Result until(const Problem& problem, const StateSet& phi, const StateSet& psi,
             const Options& options) {
  const ChoiceGraph graph = make_choice_graph(problem);
  return solve(problem, graph, classify_until(graph, problem.optimum, phi, psi), false, options);
}

Result reachability_reward(const Problem& problem, const model::RewardTable& rewards,
                           const StateSet& target, const Options& options) {
  const ChoiceGraph graph = make_choice_graph(problem);
  require_non_negative_rewards(problem.matrix, rewards, problem.values, graph);
  std::vector<Rational> reward(graph.num_choices());
  for (ChoiceId c = 0; c < graph.num_choices(); ++c)
    reward[c] = choice_reward(problem.matrix, rewards, problem.values, graph, c);
  return solve(problem, graph, classify_reward(graph, problem.optimum, target, std::move(reward)),
               true, options);
}

}  // namespace oasis::modelcheck
