#pragma once
// The values of a fixed controller under a fixed choice of distributions: a Markov chain on
// the undecided cells, x = P x + b, solved as a sparse linear system (Eigen's BiCGSTAB). Policy
// iteration uses it to guess the fixed point of a robust operator in a few solves instead of
// hundreds of sweeps. Its result is never reported as a bound: the certificates of
// docs/guarantees.md check it, rounded the safe way, before anything is kept.

#include <cstdint>
#include <optional>
#include <vector>

#include "guarantee/robust_value.hpp"

namespace oasis::guarantee {

class ChainSolver {
 public:
  // `values` gives the decided cells' fixed values (and is the start for the others).
  ChainSolver(const std::vector<std::uint8_t>& undecided, const std::vector<double>& values);

  // Adds the row of the next undecided cell, in increasing order of cells; its entries come in
  // increasing order of cells, as robust_choice gives them. Probabilities below 1e-8 are taken
  // at their target's current value rather than as unknowns: the row is only a guess.
  void add_row(std::size_t cell, const ChosenRow& row);

  // The solution on every cell (the decided ones keep their values), clamped to [0, 1], with
  // a residual at most `tolerance` times b's (1e-13 at most: a smaller one is not asked);
  // nothing when the solver does not converge.
  std::optional<std::vector<double>> solve(double tolerance);

 private:
  const std::vector<double>& values_;
  std::vector<std::int32_t> unknown_;  // per cell, its index among the undecided, or -1
  // The system (I - P) x = b in compressed rows.
  std::vector<std::int32_t> row_starts_;
  std::vector<std::int32_t> columns_;
  std::vector<double> entries_;
  std::vector<double> b_;
};

}  // namespace oasis::guarantee
