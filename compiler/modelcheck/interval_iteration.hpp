#pragma once
// The sound mode's solver: interval iteration (Haddad and Monmege, "Interval iteration
// algorithm for MDPs and IMDPs", TCS 2018; Baier, Klein, Leuschner, Parker and Wunderlich,
// "Ensuring the reliability of your model checker: interval iteration for Markov decision
// processes", CAV 2017) on a reduced system (reduced_system.hpp), in floating point rounded
// outward (outward_rounding.hpp).
//
// Two sequences of the same Bellman operator (max, min, or the one choice of a chain): the
// lower from 0, which only rises, and the upper from a bound known to lie above the solution,
// which only falls. Every iterate is a sound bound because the operator is monotone and each
// is computed rounded away from the solution; the iteration stops once upper - lower <=
// Options::precision for every variable, never on a small change between sweeps. Both
// converge to the one fixed point because the graph precomputation left none other: no end
// component among the variables (Prob0/Prob1, end components collapsed for Pmax), and for
// Rmin only end components with a positive reward, which no optimal policy keeps.
//
// The upper start is 1 for probabilities. For expected rewards it is r_max * T, with T an
// upper bound on the expected number of steps before the target: T is guessed from a
// floating-point iteration as (1 + 1/16) t + 1 and kept only when it is inductive, T >= 1 +
// P T for every allowed choice evaluated in upward rounding, which proves it is above the least
// fixed point (the guess-and-verify step of Hartmanns and Kaminski's optimistic value
// iteration, CAV 2020, on the step count, where every state's reward of 1 makes a relative
// guess inductive).

#include <cstdint>
#include <vector>

#include "modelcheck/reduced_system.hpp"

namespace oasis::modelcheck {

// The reduced system's numbers rounded down and up.
struct RoundedSystem {
  std::vector<double> constant_low;
  std::vector<double> constant_high;
  std::vector<double> probability_low;
  std::vector<double> probability_high;
  std::vector<std::uint32_t> order;  // sweep order: successors' components first
};

RoundedSystem round_outward(const ReducedSystem& system, const RationalPool& values);

struct IntervalSolution {
  std::vector<double> lower;
  std::vector<double> upper;
  std::uint64_t sweeps = 0;
};

// Throws std::runtime_error when a sweep changes nothing while some interval is still wider
// than the precision (the precision is finer than doubles can certify on this model).
IntervalSolution interval_iteration(const ReducedSystem& system, const RoundedSystem& rounded,
                                    Optimum optimum, std::vector<double> upper_start,
                                    const Options& options);

// An upper bound, per variable, on the expected number of steps before leaving the
// variables: over every policy (`policy` null) or under the given proper one.
std::vector<double> expected_steps_bound(const ReducedSystem& system, const RoundedSystem& rounded,
                                         const std::vector<std::uint32_t>* policy,
                                         const Options& options);

// The choice of each variable that is best for the midpoints of the intervals.
std::vector<std::uint32_t> greedy_policy(const ReducedSystem& system, const RoundedSystem& rounded,
                                         Optimum optimum, const IntervalSolution& solution);

}  // namespace oasis::modelcheck
