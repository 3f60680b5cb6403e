#pragma once
// A partition of the states of an explicit model into blocks: the result of bisimulation and
// the input of the quotient and the verifier.

#include <cstdint>
#include <vector>

#include "model/explicit_model.hpp"

namespace oasis::model {

using BlockIndex = std::uint32_t;

struct Partition {
  // block_of[s] is the block of state s. Blocks are numbered 0, 1, ... in the order of their
  // smallest state, so that a partition has exactly one representation and output built from
  // it is reproducible.
  std::vector<BlockIndex> block_of;
  BlockIndex num_blocks = 0;

  [[nodiscard]] std::uint32_t num_states() const {
    return static_cast<std::uint32_t>(block_of.size());
  }
  // The states of each block, ascending.
  [[nodiscard]] std::vector<std::vector<StateIndex>> blocks() const;
};

// Renumbers blocks in order of their smallest state (see Partition::block_of); `labels` may
// use any numbers below `num_labels`.
Partition canonical_partition(const std::vector<std::uint32_t>& labels);

}  // namespace oasis::model
