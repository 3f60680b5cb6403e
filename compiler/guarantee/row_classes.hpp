#pragma once
// Cells whose rows are equal, for every action: what the exact bisimulation quotient of the
// interval MDP would merge first (docs/guarantees.md, "Equal rows"). Counted, not applied: on
// a grid the enclosures make almost every row distinct, and the count says so per model.

#include <cstddef>

#include "guarantee/interval_mdp.hpp"

namespace oasis::guarantee {

// The number of classes of cells with equal rows (equal entry for entry: the same intervals
// of the same successor cells, and the same masses outside the grid and in the tails).
std::size_t distinct_rows(const IntervalMdp& mdp);

}  // namespace oasis::guarantee
