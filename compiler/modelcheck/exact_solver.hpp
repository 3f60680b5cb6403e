#pragma once
// The exact values of a reduced system (reduced_system.hpp) over GMP rationals.
//
// A Markov chain (one choice per variable) is one linear system, solved by state elimination
// (state_elimination.hpp). An MDP is solved by policy iteration with exact policy evaluation
// (Howard 1960; for reachability and stochastic shortest paths: Forejt et al., SFM 2011,
// section 4.2; Bertsekas and Tsitsiklis, "An analysis of stochastic shortest path problems",
// 1991): start from a proper policy (one that leaves the variables with probability 1, which
// make_proper ensures; the reduced system has no end components for probabilities, and for
// Rmin every end component left has a positive reward, so strict improvement keeps the policy
// proper), evaluate it exactly, switch every variable to a strictly better choice, and stop
// when none is better. The start is the greedy policy of a floating-point value iteration,
// which usually leaves one or two exact evaluations to do.

#include <cstdint>
#include <vector>

#include "modelcheck/reduced_system.hpp"

namespace oasis::modelcheck {

struct ExactSolution {
  std::vector<Rational> values;       // per variable
  std::vector<std::uint32_t> policy;  // per variable, a choice of the system
  std::uint32_t evaluations = 0;      // exact policy evaluations
};

ExactSolution solve_exactly(const ReducedSystem& system, const RationalPool& values,
                            Optimum optimum, const Options& options);

// The greedy policy of a floating-point value iteration from 0 (Gauss-Seidel, at most
// `max_sweeps` sweeps, ties to the first choice), made proper. Not sound by itself: only a
// starting point.
std::vector<std::uint32_t> approximate_policy(const ReducedSystem& system,
                                              const RationalPool& values, Optimum optimum,
                                              std::uint32_t max_sweeps);

}  // namespace oasis::modelcheck
