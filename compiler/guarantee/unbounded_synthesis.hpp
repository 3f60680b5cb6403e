#pragma once
// Unbounded objectives (`objective reach T [while S];`): the lower bound with its stationary
// controller and the upper bound, each iterated from below and certified (docs/guarantees.md,
// "Unbounded objectives").

#include "guarantee/interval_mdp.hpp"
#include "guarantee/objective_cells.hpp"
#include "guarantee/sweeper.hpp"
#include "guarantee/synthesis.hpp"

namespace oasis::guarantee {

Synthesis synthesise_unbounded(const IntervalMdp& mdp, const ObjectiveCells& cells, SweepMode mode,
                               const SynthesisOptions& options);

}  // namespace oasis::guarantee
