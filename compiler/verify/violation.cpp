#include "verify/violation.hpp"

namespace oasis::verify {

const char* kind_name(ViolationKind kind) {
  switch (kind) {
    case ViolationKind::PartitionShape:
      return "partition shape";
    case ViolationKind::EnabledActionsDiffer:
      return "enabled actions differ";
    case ViolationKind::RewardDiffers:
      return "reward differs";
    case ViolationKind::BlockProbabilityDiffers:
      return "block probability differs";
    case ViolationKind::BlocksCouldMerge:
      return "blocks could merge";
    case ViolationKind::LabelsDiffer:
      return "labels differ";
  }
  return "?";
}

bool breaks_bisimulation(ViolationKind kind) {
  return kind == ViolationKind::EnabledActionsDiffer || kind == ViolationKind::RewardDiffers ||
         kind == ViolationKind::BlockProbabilityDiffers || kind == ViolationKind::LabelsDiffer;
}

std::string describe_block(const model::ExplicitModel& model, const model::Partition& partition,
                           model::BlockIndex block) {
  // Enough members to recognise the block; the whole of a large block would drown the message.
  constexpr std::size_t kShown = 4;
  std::string text = "block " + std::to_string(block) + " {";
  std::size_t shown = 0;
  for (model::StateIndex s = 0; s < partition.num_states(); ++s) {
    if (partition.block_of[s] != block) continue;
    if (shown == kShown) {
      text += ", ...";
      break;
    }
    text += (shown++ > 0 ? ", " : "") + model.states.name(s);
  }
  return text + "}";
}

}  // namespace oasis::verify
