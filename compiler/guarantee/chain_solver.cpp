#include "guarantee/chain_solver.hpp"

#include <algorithm>
#include <cstddef>

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>

namespace oasis::guarantee {
namespace {

// The solver's relative residual target: far below the precision the certificates ask for.
constexpr double kTolerance = 1e-13;
constexpr int kMaxIterations = 2000;

using Matrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

}  // namespace

std::optional<std::vector<double>> solve_chain(const std::vector<ChosenRow>& rows,
                                               const std::vector<std::uint8_t>& undecided,
                                               const std::vector<double>& values) {
  const std::size_t cells = undecided.size();
  std::vector<std::ptrdiff_t> unknown(cells, -1);
  std::ptrdiff_t count = 0;
  for (std::size_t c = 0; c < cells; ++c)
    if (undecided[c] != 0) unknown[c] = count++;
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::VectorXd b = Eigen::VectorXd::Zero(count);
  for (std::size_t c = 0; c < cells; ++c) {
    if (unknown[c] < 0) continue;
    const std::ptrdiff_t row = unknown[c];
    entries.emplace_back(row, row, 1.0);
    b[row] = rows[c].constant;
    for (std::size_t k = 0; k < rows[c].cells.size(); ++k) {
      const std::uint32_t target = rows[c].cells[k];
      const double p = rows[c].probabilities[k];
      if (unknown[target] >= 0) {
        entries.emplace_back(row, unknown[target], -p);
      } else {
        b[row] += p * values[target];
      }
    }
  }
  Matrix system(count, count);
  system.setFromTriplets(entries.begin(), entries.end());
  entries = {};
  Eigen::BiCGSTAB<Matrix> solver;
  solver.setTolerance(kTolerance);
  solver.setMaxIterations(kMaxIterations);
  solver.compute(system);
  const Eigen::VectorXd x = solver.solve(b);
  if (solver.info() != Eigen::Success || !x.allFinite()) return std::nullopt;
  std::vector<double> solution = values;
  for (std::size_t c = 0; c < cells; ++c)
    if (unknown[c] >= 0) solution[c] = std::clamp(x[unknown[c]], 0.0, 1.0);
  return solution;
}

}  // namespace oasis::guarantee
