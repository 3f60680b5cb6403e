#include "guarantee/chain_solver.hpp"

#include <algorithm>
#include <cstddef>
#include <limits>
#include <stdexcept>

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>

namespace oasis::guarantee {
namespace {

// The tightest relative residual asked for: far below the precision the certificates need.
constexpr double kTightest = 1e-13;
constexpr int kMaxIterations = 2000;

// Entries of the guess's rows taken at their target's current value instead of as unknowns:
// the Gaussian tails' products make most entries, and these barely move the solution.
constexpr double kNegligible = 1e-8;

using Matrix = Eigen::SparseMatrix<double, Eigen::RowMajor, std::int32_t>;

}  // namespace

ChainSolver::ChainSolver(const std::vector<std::uint8_t>& undecided,
                         const std::vector<double>& values)
    : values_(values), unknown_(undecided.size(), -1) {
  std::int32_t count = 0;
  for (std::size_t c = 0; c < undecided.size(); ++c) {
    if (undecided[c] == 0) continue;
    if (count == std::numeric_limits<std::int32_t>::max())
      throw std::length_error("too many cells for the chain solver");
    unknown_[c] = count++;
  }
  row_starts_.reserve(static_cast<std::size_t>(count) + 1);
  row_starts_.push_back(0);
  b_.reserve(static_cast<std::size_t>(count));
}

void ChainSolver::add_row(std::size_t cell, const ChosenRow& row) {
  const std::int32_t self = unknown_[cell];
  double constant = row.constant;
  double diagonal = 1;
  bool diagonal_placed = false;
  const auto place_diagonal = [&] {
    columns_.push_back(self);
    entries_.push_back(diagonal);
    diagonal_placed = true;
  };
  for (std::size_t k = 0; k < row.cells.size(); ++k) {
    const double p = row.probabilities[k];
    const std::int32_t column = unknown_[row.cells[k]];
    if (column < 0 || (p < kNegligible && column != self)) {
      // A decided cell's fixed value; for a negligible entry, its target's current value,
      // which keeps the row's mass where dropping it would bias every value low.
      constant += p * values_[row.cells[k]];
    } else if (column == self) {
      diagonal -= p;
    } else {
      if (column > self && !diagonal_placed) place_diagonal();
      columns_.push_back(column);
      entries_.push_back(-p);
    }
  }
  if (!diagonal_placed) place_diagonal();
  // The diagonal was pushed before its value was final when entries came after it.
  for (std::size_t i = static_cast<std::size_t>(row_starts_.back()); i < columns_.size(); ++i)
    if (columns_[i] == self) entries_[i] = diagonal;
  b_.push_back(constant);
  row_starts_.push_back(static_cast<std::int32_t>(columns_.size()));
}

std::optional<std::vector<double>> ChainSolver::solve(double tolerance) {
  const auto count = static_cast<std::int32_t>(b_.size());
  const Eigen::Map<const Matrix> system(count, count, static_cast<std::int32_t>(columns_.size()),
                                        row_starts_.data(), columns_.data(), entries_.data());
  // Over a Ref to the map: the arrays are not copied.
  Eigen::BiCGSTAB<Matrix> solver;
  solver.setTolerance(std::max(tolerance, kTightest));
  solver.setMaxIterations(kMaxIterations);
  solver.compute(system);
  const Eigen::Map<const Eigen::VectorXd> b(b_.data(), count);
  // From the current values: policy iteration's later rounds move them little, and the
  // residual target is relative to b, so a close start saves iterations.
  Eigen::VectorXd start(count);
  for (std::size_t c = 0; c < values_.size(); ++c)
    if (unknown_[c] >= 0) start[unknown_[c]] = values_[c];
  const Eigen::VectorXd x = solver.solveWithGuess(b, start);
  if (solver.info() != Eigen::Success || !x.allFinite()) return std::nullopt;
  std::vector<double> solution = values_;
  for (std::size_t c = 0; c < solution.size(); ++c)
    if (unknown_[c] >= 0) solution[c] = std::clamp(x[unknown_[c]], 0.0, 1.0);
  return solution;
}

}  // namespace oasis::guarantee
