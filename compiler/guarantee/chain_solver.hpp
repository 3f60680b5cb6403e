#pragma once
// The values of a fixed controller under a fixed choice of distributions: a Markov chain on
// the undecided cells, x = P x + b, solved as a linear system (Eigen's BiCGSTAB). Policy
// iteration uses it to guess the fixed point of a robust operator in a few solves instead of
// hundreds of sweeps. Its result is never reported as a bound: the certificates of
// docs/guarantees.md check it, rounded the safe way, before anything is kept.

#include <cstdint>
#include <optional>
#include <vector>

#include "guarantee/robust_value.hpp"

namespace oasis::guarantee {

// rows[c] is the chosen distribution of undecided cell c (unused for the others); `values`
// gives the decided cells' fixed values. The solution on every cell (the decided ones keep
// their values), clamped to [0, 1]; nothing when the solver does not converge.
std::optional<std::vector<double>> solve_chain(const std::vector<ChosenRow>& rows,
                                               const std::vector<std::uint8_t>& undecided,
                                               const std::vector<double>& values);

}  // namespace oasis::guarantee
