// Interval iteration with outward rounding (interval_iteration.hpp).

#include "modelcheck/interval_iteration.hpp"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>

#include "modelcheck/outward_rounding.hpp"
#include "modelcheck/strongly_connected.hpp"

namespace oasis::modelcheck {
namespace {

// Variables sorted so that each strongly connected part comes after the parts it leads to:
// an acyclic stretch then settles in one sweep.
std::vector<std::uint32_t> sweep_order(const ReducedSystem& system) {
  Digraph graph;
  graph.first.assign(system.num_vars + 1, 0);
  for (std::uint32_t v = 0; v < system.num_vars; ++v) {
    graph.first[v + 1] = graph.first[v] + system.first_edge[system.first_choice[v + 1]] -
                         system.first_edge[system.first_choice[v]];
  }
  graph.next.assign(system.edge_var.begin(), system.edge_var.end());
  const Components components = strongly_connected_components(graph);
  return group_by_component(components).nodes;
}

double lower_value(const ReducedSystem& system, const RoundedSystem& rounded, std::uint32_t c,
                   const std::vector<double>& x) {
  double sum = rounded.constant_low[c];
  for (std::uint32_t e = system.first_edge[c]; e < system.first_edge[c + 1]; ++e)
    sum = add_down(sum, multiply_down(rounded.probability_low[e], x[system.edge_var[e]]));
  return sum;
}

double upper_value(const ReducedSystem& system, const RoundedSystem& rounded, std::uint32_t c,
                   const std::vector<double>& x) {
  double sum = rounded.constant_high[c];
  for (std::uint32_t e = system.first_edge[c]; e < system.first_edge[c + 1]; ++e)
    sum = add_up(sum, multiply_up(rounded.probability_high[e], x[system.edge_var[e]]));
  return sum;
}

double pick(Optimum optimum, double a, double b) {
  return optimum == Optimum::kMin ? std::min(a, b) : std::max(a, b);
}

std::string width_text(double width) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", width);
  return text;
}

}  // namespace

RoundedSystem round_outward(const ReducedSystem& system, const RationalPool& values) {
  RoundedSystem rounded;
  for (const Rational& constant : system.constant) {
    rounded.constant_low.push_back(rational_down(constant));
    rounded.constant_high.push_back(rational_up(constant));
  }
  for (const ValueId p : system.edge_probability) {
    rounded.probability_low.push_back(rational_down(values[p]));
    rounded.probability_high.push_back(rational_up(values[p]));
  }
  rounded.order = sweep_order(system);
  return rounded;
}

IntervalSolution interval_iteration(const ReducedSystem& system, const RoundedSystem& rounded,
                                    Optimum optimum, std::vector<double> upper_start,
                                    const Options& options) {
  IntervalSolution solution;
  solution.lower.assign(system.num_vars, 0);
  solution.upper = std::move(upper_start);
  std::vector<double>& lower = solution.lower;
  std::vector<double>& upper = solution.upper;
  for (;;) {
    ++solution.sweeps;
    bool changed = false;
    double width = 0;
    for (const std::uint32_t v : rounded.order) {
      const std::uint32_t first = system.first_choice[v];
      double low = lower_value(system, rounded, first, lower);
      double high = upper_value(system, rounded, first, upper);
      for (std::uint32_t c = first + 1; c < system.first_choice[v + 1]; ++c) {
        low = pick(optimum, low, lower_value(system, rounded, c, lower));
        high = pick(optimum, high, upper_value(system, rounded, c, upper));
      }
      if (low > lower[v]) {
        lower[v] = low;
        changed = true;
      }
      if (high < upper[v]) {
        upper[v] = high;
        changed = true;
      }
      width = std::max(width, round_up(upper[v] - lower[v]));
    }
    if (width <= options.precision) return solution;
    if (!changed) {
      throw std::runtime_error(
          "interval iteration stalled at width " + width_text(width) + " after " +
          std::to_string(solution.sweeps) +
          " sweeps: the precision is finer than floating point can certify on this model; "
          "ask for a larger precision or the exact mode");
    }
    if (options.progress && solution.sweeps % 1000 == 0) {
      options.progress("interval iteration: " + std::to_string(solution.sweeps) +
                       " sweeps, width " + width_text(width));
    }
  }
}

std::vector<double> expected_steps_bound(const ReducedSystem& system, const RoundedSystem& rounded,
                                         const std::vector<std::uint32_t>* policy,
                                         const Options& options) {
  auto choices = [&](std::uint32_t v) {
    return policy ? std::pair{(*policy)[v], (*policy)[v] + 1}
                  : std::pair{system.first_choice[v], system.first_choice[v + 1]};
  };
  // Steps: reward 1 per step, i.e. the system with every constant replaced by 1.
  RoundedSystem steps = rounded;
  steps.constant_low.assign(system.num_choices(), 1);
  steps.constant_high.assign(system.num_choices(), 1);
  std::vector<double> guess(system.num_vars, 0);
  std::vector<double> bound(system.num_vars);
  constexpr std::uint64_t kMaxSweeps = 10'000'000;
  for (std::uint64_t sweep = 1; sweep <= kMaxSweeps; ++sweep) {
    for (const std::uint32_t v : rounded.order) {
      const auto [begin, end] = choices(v);
      for (std::uint32_t c = begin; c < end; ++c)
        guess[v] = std::max(guess[v], upper_value(system, steps, c, guess));
    }
    if (sweep % 16 != 1) continue;
    for (std::uint32_t v = 0; v < system.num_vars; ++v)
      bound[v] = add_up(multiply_up(guess[v], 1.0 + 1.0 / 16), 1);
    bool inductive = true;
    for (std::uint32_t v = 0; v < system.num_vars && inductive; ++v) {
      const auto [begin, end] = choices(v);
      for (std::uint32_t c = begin; c < end && inductive; ++c)
        inductive = upper_value(system, steps, c, bound) <= bound[v];
    }
    if (inductive) return bound;
    if (options.progress && sweep % 4096 == 1) {
      options.progress("sound rewards: bounding the expected steps, " + std::to_string(sweep) +
                       " sweeps");
    }
  }
  throw std::runtime_error("no upper bound on the expected steps to the target was found within " +
                           std::to_string(kMaxSweeps) + " sweeps");
}

std::vector<std::uint32_t> greedy_policy(const ReducedSystem& system, const RoundedSystem& rounded,
                                         Optimum optimum, const IntervalSolution& solution) {
  std::vector<double> middle(system.num_vars);
  for (std::uint32_t v = 0; v < system.num_vars; ++v)
    middle[v] = solution.lower[v] / 2 + solution.upper[v] / 2;
  std::vector<std::uint32_t> policy(system.num_vars);
  for (std::uint32_t v = 0; v < system.num_vars; ++v) {
    policy[v] = system.first_choice[v];
    double best = lower_value(system, rounded, policy[v], middle);
    for (std::uint32_t c = policy[v] + 1; c < system.first_choice[v + 1]; ++c) {
      const double q = lower_value(system, rounded, c, middle);
      if (optimum == Optimum::kMin ? q < best : q > best) {
        best = q;
        policy[v] = c;
      }
    }
  }
  return policy;
}

}  // namespace oasis::modelcheck
