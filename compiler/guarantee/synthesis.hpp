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
  // Unbounded objectives: 2 or more iterate the lower and the upper bound on two threads.
  unsigned jobs = 1;
  std::uint64_t max_sweeps = 100'000;
  // Called after each sweep with (sweep, the largest change of the lower bound, or the gap
  // for bounded objectives); may throw to stop.
  std::function<void(std::uint64_t, double)> progress;
};

struct Synthesis {
  std::vector<double> lower;  // per cell, at step 0
  std::vector<double> upper;
  // Bounded objectives: controller[k][cell] is the action at step k (k = 0 .. N-1).
  // Unbounded: one table, used at every step.
  std::vector<std::vector<std::uint32_t>> controller;
  std::uint64_t sweeps = 0;             // of the optimal lower bound (and upper bound)
  std::uint64_t evaluation_sweeps = 0;  // of the controller's own lower bound (unbounded)
  double largest_gap = 0;
  bool gap_closed = true;  // unbounded: the gap reached SynthesisOptions::gap
  std::string stop_reason;
};

Synthesis synthesise(const IntervalMdp& mdp, const model::GuaranteeObjective& objective,
                     const ObjectiveCells& cells, const SynthesisOptions& options);

}  // namespace oasis::guarantee
