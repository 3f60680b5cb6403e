#pragma once
// Whether a bisimulation is the coarsest one: no two of its blocks are bisimilar.

#include <cstddef>

#include "model/explicit_model.hpp"
#include "model/partition.hpp"
#include "verify/violation.hpp"

namespace oasis::verify {

// `partition` must be a bisimulation (check_bisimulation). Builds the quotient, the MDP whose
// states are the blocks, each behaving as its first member does, and refines it naively: start
// with one class, then repeatedly split classes by (class, for each enabled action its reward
// and probability of reaching each class) until the number of classes stops changing. The
// partition is the coarsest bisimulation iff this ends with one class per block, since the
// coarsest bisimulation of the model is that of the quotient pulled back to the states.
// Quadratic in the number of blocks in the worst case (a chain); simple on purpose.
// With `label_class`, the naive refinement starts from the blocks' classes of respected labels
// instead of one class.
VerificationResult check_coarsest(const model::ExplicitModel& model, std::size_t context,
                                  const model::Partition& partition,
                                  const std::vector<std::uint32_t>& label_class = {});

}  // namespace oasis::verify
