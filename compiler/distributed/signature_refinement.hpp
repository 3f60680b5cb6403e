#pragma once
// The coarsest probabilistic bisimulation (Definition 1) of a model spread over ranks, by
// signature refinement. Each round every rank learns the current block of every state its
// edges lead to, and computes for each state it owns an exact signature:
//   round 0:  for each enabled action, in order: the action and its reward R(s, a);
//   round k:  the state's block, then for each enabled action: the action and the exact mass
//             P(B | s, a) for each block B it reaches, in block order.
// A signature is sent to the rank its hash names, which numbers the distinct ones it receives;
// the numbers become global block ids through an all-gather of the counts. The state's own
// block is part of its signature, so each round refines the last, and the first round that
// adds no block has reached the coarsest bisimulation. docs/bisimulation.md gives the cost.

#include <cstdint>
#include <functional>
#include <vector>

#include "distributed/communicator.hpp"
#include "distributed/owned_model.hpp"

namespace oasis::distributed {

struct DistributedOptions {
  // Add probabilities with GMP even when integers over a common denominator are exact (for
  // tests: both exact paths must agree).
  bool rational_sums = false;
  // Called on every rank at the start of each round with the round and the blocks so far.
  std::function<void(std::uint32_t round, std::uint64_t blocks)> on_round;
};

struct DistributedPartition {
  std::vector<std::uint32_t> block_of_owned;  // per local state; ids are not canonical
  std::uint64_t num_blocks = 0;
  std::uint32_t rounds = 0;
  bool exact_integer_sums = false;
};

// Collective. On return the edge targets of `owned` are the targets' blocks (ids of
// block_of_owned), which is what a quotient needs of them.
DistributedPartition refine_distributed(OwnedModel& owned, const Communicator& communicator,
                                        const DistributedOptions& options = {});

}  // namespace oasis::distributed
