#pragma once
// Controller synthesis with guarantees on the interval MDP (docs/guarantees.md): for every
// cell a lower bound on the probability that the true system meets the objective from any
// point of the cell under the synthesised controller, and an upper bound that no controller
// can beat from any point of the cell.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "guarantee/interval_mdp.hpp"
#include "guarantee/objective_cells.hpp"

namespace oasis::guarantee {

struct SynthesisOptions {
  // Unbounded objectives: a gap (upper minus lower) at most this counts as closed.
  double gap = 1e-6;
  // Each bound's iteration stops when no value moves by more than this in a sweep (the bounds
  // are sound at any stop; the gap left is reported).
  double stall = 1e-9;
  // Unbounded objectives: each bound's iteration also stops once a certified bound is within
  // this of the iteration's limit, as estimated from its rate (docs/guarantees.md).
  double precision = 1e-6;
  // Unbounded objectives: 2 or more iterate the lower and the upper bound on two threads.
  unsigned jobs = 1;
  std::uint64_t max_sweeps = 100'000;
  // Unbounded objectives: guess the bounds by policy iteration (linear solves) before and
  // beside the sweeps. Off, only the sweeps and their extrapolations guess (for tests and
  // comparisons: the certificates are the same).
  bool policy_iteration = true;
  // Called after each sweep with (sweep, the largest change of the lower bound, or the gap
  // for bounded objectives); may throw to stop.
  using Progress = std::function<void(std::uint64_t, double)>;
  Progress progress;
};

// The mean of per-cell values (0 for none).
double mean(const std::vector<double>& values);

struct Synthesis {
  std::vector<double> lower;  // per cell, at step 0
  std::vector<double> upper;
  // Bounded objectives: controller[k][cell] is the action at step k (k = 0 .. N-1).
  // Unbounded: one table, used at every step.
  std::vector<std::vector<std::uint32_t>> controller;
  std::uint64_t sweeps = 0;             // of the lower bound (bounded: of both)
  std::uint64_t evaluation_sweeps = 0;  // unbounded: of the controller's own value, if needed
  std::uint64_t upper_sweeps = 0;       // unbounded: of the upper bound, verifications aside
  std::uint64_t policy_rounds = 0;      // unbounded: linear solves of the lower bound's guess
  // Unbounded: how each bound was obtained (docs/guarantees.md, "Unbounded objectives").
  std::string lower_method;
  std::string upper_method;
  double largest_gap = 0;

  [[nodiscard]] double lower_mean() const { return mean(lower); }
  [[nodiscard]] double upper_mean() const { return mean(upper); }
  bool gap_closed = true;  // unbounded: the gap reached SynthesisOptions::gap
  std::string stop_reason;
};

// The largest upper minus lower bound over the cells. Throws std::logic_error if a lower bound
// is above its upper bound: both are proven, so that would be a bug.
double largest_gap(const std::vector<double>& lower, const std::vector<double>& upper);

Synthesis synthesise(const IntervalMdp& mdp, const model::GuaranteeObjective& objective,
                     const ObjectiveCells& cells, const SynthesisOptions& options);

}  // namespace oasis::guarantee
