#pragma once
// Whether a partition is a bisimulation of one context (Definition 1 of the paper), checked
// directly and exactly: every member of a block is compared with the block's first member.
// Deliberately shares no code with bisim/refinement.cpp, whose results it checks.

#include <cstddef>

#include "model/explicit_model.hpp"
#include "model/partition.hpp"
#include "verify/violation.hpp"

namespace oasis::verify {

// For every block B with first member r and every other member s, and every action a:
//   a is enabled in both or in neither (else EnabledActionsDiffer);
//   when enabled, R(s, a) = R(r, a) (else RewardDiffers) and P(C | s, a) = P(C | r, a) for
//   every block C (else BlockProbabilityDiffers).
// Rewards of disabled choices are not compared: such a choice does not exist, and the .aut
// encoding (docs/formats.md) has no way to write its reward.
// Enabled actions and rewards are checked for all blocks before any probability, so the
// violation reported is the most basic one. `partition` must have a valid shape
// (check_partition_shape).
// With `label_class` (one class of respected labels per state), the states of a block must
// also share their class.
VerificationResult check_bisimulation(const model::ExplicitModel& model, std::size_t context,
                                      const model::Partition& partition,
                                      const std::vector<std::uint32_t>& label_class = {});

}  // namespace oasis::verify
