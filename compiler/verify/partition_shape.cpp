#include "verify/partition_shape.hpp"

#include <vector>

namespace oasis::verify {
namespace {

VerificationResult shape_violation(std::string message) {
  Violation violation;
  violation.kind = ViolationKind::PartitionShape;
  violation.message = std::move(message);
  return {std::move(violation)};
}

}  // namespace

VerificationResult check_partition_shape(const model::ExplicitModel& model,
                                         const model::Partition& partition) {
  if (partition.num_states() != model.num_states()) {
    return shape_violation("the partition has " + std::to_string(partition.num_states()) +
                           " states but the model has " + std::to_string(model.num_states()));
  }
  std::vector<bool> used(partition.num_blocks, false);
  for (model::StateIndex s = 0; s < partition.num_states(); ++s) {
    const model::BlockIndex block = partition.block_of[s];
    if (block >= partition.num_blocks) {
      VerificationResult result = shape_violation(
          "state " + model.states.name(s) + " is in block " + std::to_string(block) +
          " but the partition has only " + std::to_string(partition.num_blocks) + " blocks");
      result.violation->state = s;
      result.violation->block = block;
      return result;
    }
    used[block] = true;
  }
  for (model::BlockIndex block = 0; block < partition.num_blocks; ++block) {
    if (used[block]) continue;
    VerificationResult result =
        shape_violation("block " + std::to_string(block) + " of " +
                        std::to_string(partition.num_blocks) + " has no states");
    result.violation->block = block;
    return result;
  }
  return {};
}

}  // namespace oasis::verify
