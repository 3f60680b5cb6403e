#pragma once
// Where the disturbance can keep a run from ever being decided (docs/guarantees.md, "The
// controller's certificate"). Under a fixed controller, a *trap* is a set M of undecided cells
// (neither fixed at 1 nor at 0) such that from every cell of M some distribution of its row puts
// all its mass on M: no mass leaves the grid, none is truncated, and every axis outcome that
// must get mass (a positive lower bound) stays in M. Without a trap, the lower bound's Bellman
// operator under the controller has a single fixed point, so any post-fixed point (v ≤ B v) is
// a lower bound on what the controller attains.

#include <cstdint>
#include <vector>

#include "guarantee/interval_mdp.hpp"

namespace oasis::guarantee {

// The greatest trap under `policy` (one action per cell), as a flag per cell. `undecided[c]`
// is 1 for the cells whose value is not fixed. It is computed by removing, until nothing
// changes, every cell none of whose distributions can stay in the remaining set; it errs on
// the side of keeping a cell (a row whose upper bounds reach 1 only within 1e-9 can stay), so
// an empty result is a proof. After 1,000 passes it stops with a superset of the greatest
// trap, which is as good for that purpose.
std::vector<std::uint8_t> greatest_trap(const IntervalMdp& mdp,
                                        const std::vector<std::uint8_t>& undecided,
                                        const std::vector<std::uint32_t>& policy);

}  // namespace oasis::guarantee
