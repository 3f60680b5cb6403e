#pragma once
// Whether a Partition is a partition of the model's states at all: every later check
// indexes by block_of, so it runs first.

#include "model/explicit_model.hpp"
#include "model/partition.hpp"
#include "verify/violation.hpp"

namespace oasis::verify {

// One entry per state, every block id below num_blocks, no empty block. Blocks need not be
// numbered in order of their smallest state: any numbering describes the same partition.
VerificationResult check_partition_shape(const model::ExplicitModel& model,
                                         const model::Partition& partition);

}  // namespace oasis::verify
