// Exact policy iteration over the reduced system (exact_solver.hpp).

#include "modelcheck/exact_solver.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "modelcheck/number_limits.hpp"
#include "modelcheck/state_elimination.hpp"

namespace oasis::modelcheck {
namespace {

bool better(Optimum optimum, const Rational& candidate, const Rational& incumbent) {
  return optimum == Optimum::kMin ? candidate < incumbent : candidate > incumbent;
}

double choice_value(const ReducedSystem& system, const std::vector<double>& probability,
                    const std::vector<double>& constant, std::uint32_t c,
                    const std::vector<double>& x) {
  double sum = constant[c];
  for (std::uint32_t e = system.first_edge[c]; e < system.first_edge[c + 1]; ++e)
    sum += probability[e] * x[system.edge_var[e]];
  return sum;
}

LinearEquations equations_of(const ReducedSystem& system, const RationalPool& values,
                             const std::vector<std::uint32_t>& policy) {
  LinearEquations equations;
  equations.rows.resize(system.num_vars);
  equations.constant.resize(system.num_vars);
  for (std::uint32_t v = 0; v < system.num_vars; ++v) {
    const std::uint32_t c = policy[v];
    equations.constant[v] = system.constant[c];
    SparseRow& row = equations.rows[v];
    for (std::uint32_t e = system.first_edge[c]; e < system.first_edge[c + 1]; ++e)
      row.push_back({system.edge_var[e], values[system.edge_probability[e]]});
    // A collapsed end component can send two edges to one variable: merge them.
    std::sort(row.begin(), row.end(),
              [](const Entry& a, const Entry& b) { return a.column < b.column; });
    std::size_t kept = 0;
    for (std::size_t i = 0; i < row.size(); ++i) {
      if (kept > 0 && row[kept - 1].column == row[i].column) {
        row[kept - 1].value += row[i].value;
      } else {
        row[kept++] = std::move(row[i]);
      }
    }
    row.resize(kept);
  }
  return equations;
}

Rational exact_choice_value(const ReducedSystem& system, const RationalPool& values,
                            std::uint32_t c, const std::vector<Rational>& x) {
  Rational sum = system.constant[c];
  for (std::uint32_t e = system.first_edge[c]; e < system.first_edge[c + 1]; ++e)
    sum += values[system.edge_probability[e]] * x[system.edge_var[e]];
  return sum;
}

// One improvement step; returns whether some variable switched.
bool improve(const ReducedSystem& system, const RationalPool& values, Optimum optimum,
             const std::vector<Rational>& x, std::vector<std::uint32_t>& policy) {
  bool switched = false;
  for (std::uint32_t v = 0; v < system.num_vars; ++v) {
    Rational best = x[v];
    for (std::uint32_t c = system.first_choice[v]; c < system.first_choice[v + 1]; ++c) {
      if (c == policy[v]) continue;
      Rational candidate = exact_choice_value(system, values, c, x);
      if (!better(optimum, candidate, best)) continue;
      best = std::move(candidate);
      policy[v] = c;
      switched = true;
    }
  }
  return switched;
}

// Enough sweeps for a good start on small models, and a bounded amount of floating-point work
// (about 5 * 10^7 edge visits) on large ones.
std::uint32_t start_sweeps(const ReducedSystem& system) {
  const std::size_t work = std::max<std::size_t>(1, system.edge_var.size() + system.num_vars);
  return static_cast<std::uint32_t>(std::clamp<std::size_t>(50'000'000 / work, 10, 10'000));
}

bool one_choice_each(const ReducedSystem& system) {
  for (std::uint32_t v = 0; v < system.num_vars; ++v) {
    if (system.first_choice[v + 1] - system.first_choice[v] != 1) return false;
  }
  return true;
}

}  // namespace

std::vector<std::uint32_t> approximate_policy(const ReducedSystem& system,
                                              const RationalPool& values, Optimum optimum,
                                              std::uint32_t max_sweeps) {
  std::vector<double> probability(system.edge_probability.size());
  for (std::size_t e = 0; e < probability.size(); ++e)
    probability[e] = to_double(values[system.edge_probability[e]]);
  std::vector<double> constant(system.num_choices());
  for (std::uint32_t c = 0; c < system.num_choices(); ++c)
    constant[c] = to_double(system.constant[c]);
  std::vector<double> x(system.num_vars, 0);
  std::vector<std::uint32_t> policy(system.first_choice.begin(), system.first_choice.end() - 1);
  const bool minimise = optimum == Optimum::kMin;
  for (std::uint32_t sweep = 0; sweep < max_sweeps; ++sweep) {
    double change = 0;
    for (std::uint32_t v = 0; v < system.num_vars; ++v) {
      for (std::uint32_t c = system.first_choice[v]; c < system.first_choice[v + 1]; ++c) {
        const double q = choice_value(system, probability, constant, c, x);
        const double current = choice_value(system, probability, constant, policy[v], x);
        if (minimise ? q < current : q > current) policy[v] = c;
      }
      const double updated = choice_value(system, probability, constant, policy[v], x);
      change = std::max(change, std::abs(updated - x[v]) / std::max(1.0, std::abs(updated)));
      x[v] = updated;
    }
    if (change < 1e-12) break;
  }
  return make_proper(system, std::move(policy));
}

ExactSolution solve_exactly(const ReducedSystem& system, const RationalPool& values,
                            Optimum optimum, const Options& options) {
  check_exact_state_count(system.num_vars, options);
  ExactSolution solution;
  const bool chain = one_choice_each(system);
  solution.policy =
      chain ? std::vector<std::uint32_t>(system.first_choice.begin(), system.first_choice.end() - 1)
            : approximate_policy(system, values, optimum, start_sweeps(system));
  for (;;) {
    solution.values = solve_by_elimination(equations_of(system, values, solution.policy), options);
    ++solution.evaluations;
    if (chain || !improve(system, values, optimum, solution.values, solution.policy)) break;
    if (options.progress) {
      options.progress("exact: policy iteration, " + std::to_string(solution.evaluations) +
                       " evaluations");
    }
  }
  return solution;
}

}  // namespace oasis::modelcheck
