// The step-bounded operators of engine.hpp: `bounded_until`, `next`, `cumulative_reward` and
// `instantaneous_reward`, all one backward induction over the steps,
//     x_0 given,   x_{i+1}(s) = x_i(s) on frozen states, else opt_a (r(s, a) + sum_t P(s,a,t)
//     x_i(t)),
// with the result x_k (Baier and Katoen, Principles of Model Checking, 10.1.1 and 10.6; Forejt
// et al., SFM 2011, 3.2 and 4.1). In exact mode over GMP rationals; in sound mode in interval
// arithmetic, every number and operation rounded outward, so the interval's width comes from
// rounding alone. The optimal scheduler depends on the steps left: by_step[i] is the choice at
// step i, made in iteration k - i.

#include <cstdio>
#include <string>
#include <utility>

#include "modelcheck/choice_graph.hpp"
#include "modelcheck/engine.hpp"
#include "modelcheck/number_limits.hpp"
#include "modelcheck/outward_rounding.hpp"

namespace oasis::modelcheck {
namespace {

struct Induction {
  std::uint32_t steps = 0;
  std::vector<Rational> initial;  // x_0, per state
  std::vector<Rational> reward;   // per choice of the graph, added every step; or empty
  StateSet frozen;                // states whose value stays x_0; or empty
};

bool is_frozen(const Induction& induction, model::StateIndex s) {
  return !induction.frozen.empty() && induction.frozen[s];
}

bool better(Optimum optimum, const Rational& a, const Rational& b) {
  return optimum == Optimum::kMin ? a < b : a > b;
}

std::vector<Rational> exact_induction(const ChoiceGraph& graph, const Problem& problem,
                                      const Induction& induction, const Options& options,
                                      Scheduler& scheduler) {
  check_exact_state_count(graph.num_states, options);
  std::vector<Rational> x = induction.initial;
  std::vector<Rational> next(graph.num_states);
  for (std::uint32_t iteration = 1; iteration <= induction.steps; ++iteration) {
    std::vector<model::ActionIndex>* decisions =
        scheduler.by_step.empty() ? nullptr : &scheduler.by_step[induction.steps - iteration];
    for (model::StateIndex s = 0; s < graph.num_states; ++s) {
      if (is_frozen(induction, s)) {
        next[s] = x[s];
        continue;
      }
      for (ChoiceId c = graph.first_choice[s]; c < graph.first_choice[s + 1]; ++c) {
        Rational q = induction.reward.empty() ? Rational(0) : induction.reward[c];
        for (std::uint32_t e = graph.first_edge[c]; e < graph.first_edge[c + 1]; ++e)
          q += problem.values[graph.probability[e]] * x[graph.target[e]];
        if (c != graph.first_choice[s] && !better(problem.optimum, q, next[s])) continue;
        next[s] = std::move(q);
        if (decisions) (*decisions)[s] = graph.action[c];
      }
      check_number_size(next[s], options.max_number_bits);
    }
    std::swap(x, next);
  }
  return x;
}

struct Bounds {
  std::vector<double> lower;
  std::vector<double> upper;
};

std::pair<double, double> sound_choice(const ChoiceGraph& graph, const Problem& problem,
                                       const Induction& induction, const Bounds& x, ChoiceId c) {
  double low = induction.reward.empty() ? 0 : rational_down(induction.reward[c]);
  double high = induction.reward.empty() ? 0 : rational_up(induction.reward[c]);
  for (std::uint32_t e = graph.first_edge[c]; e < graph.first_edge[c + 1]; ++e) {
    const Rational& p = problem.values[graph.probability[e]];
    low = add_down(low, multiply_down(rational_down(p), x.lower[graph.target[e]]));
    high = add_up(high, multiply_up(rational_up(p), x.upper[graph.target[e]]));
  }
  return {low, high};
}

Bounds sound_induction(const ChoiceGraph& graph, const Problem& problem, const Induction& induction,
                       Scheduler& scheduler) {
  Bounds x;
  for (const Rational& value : induction.initial) {
    x.lower.push_back(rational_down(value));
    x.upper.push_back(rational_up(value));
  }
  Bounds next = x;
  const bool minimise = problem.optimum == Optimum::kMin;
  for (std::uint32_t iteration = 1; iteration <= induction.steps; ++iteration) {
    std::vector<model::ActionIndex>* decisions =
        scheduler.by_step.empty() ? nullptr : &scheduler.by_step[induction.steps - iteration];
    for (model::StateIndex s = 0; s < graph.num_states; ++s) {
      if (is_frozen(induction, s)) continue;
      double best_middle = 0;
      for (ChoiceId c = graph.first_choice[s]; c < graph.first_choice[s + 1]; ++c) {
        const auto [low, high] = sound_choice(graph, problem, induction, x, c);
        const bool first = c == graph.first_choice[s];
        // The bounds of the optimum are the optimum of the bounds.
        next.lower[s] =
            first ? low : (minimise ? std::min(next.lower[s], low) : std::max(next.lower[s], low));
        next.upper[s] =
            first ? high
                  : (minimise ? std::min(next.upper[s], high) : std::max(next.upper[s], high));
        const double middle = low / 2 + high / 2;
        if (first || (minimise ? middle < best_middle : middle > best_middle)) {
          best_middle = middle;
          if (decisions) (*decisions)[s] = graph.action[c];
        }
      }
    }
    std::swap(x, next);
    next = x;
  }
  return x;
}

Result run(const Problem& problem, const Induction& induction, const Options& options,
           const std::string& what) {
  const ChoiceGraph graph = make_choice_graph(problem);
  Scheduler scheduler;
  const bool want = options.want_scheduler && problem.optimum != Optimum::kNone;
  if (want) {
    scheduler.by_step.assign(
        induction.steps, std::vector<model::ActionIndex>(graph.num_states, Scheduler::kAnyAction));
  }
  Result result;
  result.values.resize(graph.num_states);
  const std::string steps = std::to_string(induction.steps) +
                            (induction.steps == 1 ? " step" : " steps") + " of backward induction";
  if (options.mode == Mode::kExact) {
    std::vector<Rational> x = exact_induction(graph, problem, induction, options, scheduler);
    for (model::StateIndex s = 0; s < graph.num_states; ++s) {
      const double nearest = to_double(x[s]);
      result.values[s] = {false, std::move(x[s]), nearest, nearest};
    }
    result.method = "exact: " + what + ", " + steps + " over GMP rationals";
  } else {
    const Bounds x = sound_induction(graph, problem, induction, scheduler);
    for (model::StateIndex s = 0; s < graph.num_states; ++s)
      result.values[s] = {false, Rational(0), x.lower[s], x.upper[s]};
    result.method =
        "sound: " + what + ", " + steps + " in interval arithmetic with outward rounding";
  }
  if (want) result.scheduler = std::move(scheduler);
  return result;
}

std::vector<Rational> indicator(const StateSet& set) {
  std::vector<Rational> x(set.size());
  for (std::size_t s = 0; s < set.size(); ++s)
    x[s] = set[s] ? 1 : 0;
  return x;
}

}  // namespace

Result bounded_until(const Problem& problem, const StateSet& phi, const StateSet& psi,
                     std::uint32_t steps, const Options& options) {
  Induction induction;
  induction.steps = steps;
  induction.initial = indicator(psi);
  induction.frozen.resize(psi.size());
  for (std::size_t s = 0; s < psi.size(); ++s)
    induction.frozen[s] = psi[s] || !phi[s];
  return run(problem, induction, options, "bounded until");
}

Result next(const Problem& problem, const StateSet& psi, const Options& options) {
  Induction induction;
  induction.steps = 1;
  induction.initial = indicator(psi);
  return run(problem, induction, options, "next");
}

Result cumulative_reward(const Problem& problem, const model::RewardTable& rewards,
                         std::uint32_t steps, const Options& options) {
  const ChoiceGraph graph = make_choice_graph(problem);
  require_non_negative_rewards(problem.matrix, rewards, problem.values, graph);
  Induction induction;
  induction.steps = steps;
  induction.initial.assign(graph.num_states, Rational(0));
  for (ChoiceId c = 0; c < graph.num_choices(); ++c)
    induction.reward.push_back(choice_reward(problem.matrix, rewards, problem.values, graph, c));
  return run(problem, induction, options, "cumulative reward");
}

Result instantaneous_reward(const Problem& problem, const model::RewardTable& rewards,
                            std::uint32_t steps, const Options& options) {
  const ChoiceGraph graph = make_choice_graph(problem);
  require_non_negative_rewards(problem.matrix, rewards, problem.values, graph);
  Induction induction;
  induction.steps = steps;
  for (model::StateIndex s = 0; s < graph.num_states; ++s)
    induction.initial.push_back(rewards.state.empty() ? Rational(0)
                                                      : problem.values[rewards.state[s]]);
  return run(problem, induction, options, "instantaneous reward");
}

}  // namespace oasis::modelcheck
