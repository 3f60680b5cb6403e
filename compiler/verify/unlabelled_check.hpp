#pragma once
// The independent check of a partition under Storm's MDP semantics (`quotient --choices
// unlabelled`, bisim/unlabelled_refinement.hpp): a state's choices are a set of
// distributions, their action names ignored. Written to share nothing with the engine: each
// state's choices are compared as a std::set of exact (choice reward, block distribution)
// values.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "model/explicit_model.hpp"
#include "model/partition.hpp"
#include "verify/violation.hpp"

namespace oasis::verify {

// Every member of a block, against the block's first member: the same respected labels
// (LabelsDiffer) and the same set of choices, each choice its reward R(s, a) (state plus
// choice reward, as Definition 1 counts it) and its probability of reaching every block
// (BlockProbabilityDiffers); two states with no enabled action, the same state reward
// (RewardDiffers).
// `partition` must have a valid shape (check_partition_shape).
VerificationResult check_unlabelled_bisimulation(const model::ExplicitModel& model,
                                                 std::size_t context,
                                                 const model::Partition& partition,
                                                 const std::vector<std::uint32_t>& label_class);

// `partition` must pass check_unlabelled_bisimulation. Refines naively from the respected
// labels (and the state reward of states with no enabled action): classes are split by (class, the
// set of choices over classes) until their number stops changing. The partition is the coarsest iff
// it has as many blocks as that fixpoint has classes (a bisimulation refines the coarsest one);
// otherwise two blocks that the fixpoint puts in one class are reported (BlocksCouldMerge).
VerificationResult check_unlabelled_coarsest(const model::ExplicitModel& model, std::size_t context,
                                             const model::Partition& partition,
                                             const std::vector<std::uint32_t>& label_class);

}  // namespace oasis::verify
