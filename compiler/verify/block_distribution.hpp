#pragma once
// P(B | s, a) for every block B that s reaches under a: the quantity Definition 1 compares.

#include <utility>
#include <vector>

#include "model/explicit_model.hpp"
#include "model/partition.hpp"

namespace oasis::verify {

// (block, exact probability) pairs sorted by block, one per block reached with positive
// probability; empty when a is not enabled in s. `block_of` maps states to any block numbers.
std::vector<std::pair<model::BlockIndex, Rational>> block_distribution(
    const model::ExplicitModel& model, std::size_t context,
    const std::vector<model::BlockIndex>& block_of, model::StateIndex s, model::ActionIndex a);

}  // namespace oasis::verify
