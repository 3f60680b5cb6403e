#pragma once
// The quotient MDP (Z, A, P^Z, R^Z) of one context under a bisimulation: one state per
// block, named z0, z1, ... in block order; P^Z(z' | z, a) and R^Z(z, a) are those of the
// block's smallest state, which every other member shares when the partition is a
// bisimulation.

#include "model/explicit_model.hpp"
#include "model/partition.hpp"

namespace oasis::bisim {

// A one-context model named like `model`, whose context has the context's name.
model::ExplicitModel build_quotient(const model::ExplicitModel& model, std::size_t context,
                                    const model::Partition& partition);

}  // namespace oasis::bisim
