#pragma once
// The exact solution of x = A x + b over GMP rationals, for the linear systems of Markov chain
// reachability and expected rewards (and of policy evaluation), where A is substochastic and
// every variable leaves with probability 1, so that I - A is invertible.
//
// Method: the variables are split into strongly connected components, which are solved one by
// one in reverse topological order (a component's equations only refer to itself and to
// components already solved). Within a component, Gaussian elimination in the form of state
// elimination: eliminating x_k = (b_k + sum_{j != k} a_kj x_j) / (1 - a_kk) substitutes it
// into every equation that mentions it; back-substitution in reverse order gives the values.
// The order is greedy minimum degree (fewest (rows that mention k) x (entries of row k)
// first), which keeps chains and trees free of fill and bounds it on typical models. All
// coefficients stay non-negative, so nothing cancels and 1 - a_kk > 0 throughout.
//
// Limits: every computed number is checked against Options::max_number_bits, and the number
// of entries held at once against kMaxEliminationEntries; both throw ExactLimitExceeded.

#include <cstdint>
#include <vector>

#include "modelcheck/engine.hpp"

namespace oasis::modelcheck {

struct Entry {
  std::uint32_t column = 0;
  Rational value;
};
// Sorted by column, columns distinct.
using SparseRow = std::vector<Entry>;

struct LinearEquations {
  std::vector<SparseRow> rows;
  std::vector<Rational> constant;
};

std::vector<Rational> solve_by_elimination(LinearEquations equations, const Options& options);

}  // namespace oasis::modelcheck
