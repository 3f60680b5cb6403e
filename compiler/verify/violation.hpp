#pragma once
// What the verifier reports when a partition is not the coarsest bisimulation of a context:
// the first violation found, with the states, action and blocks involved, so that a caller
// can check the claim or print it.

#include <optional>
#include <string>

#include "model/explicit_model.hpp"
#include "model/partition.hpp"

namespace oasis::verify {

enum class ViolationKind {
  PartitionShape,           // wrong number of states, a block id out of range, an empty block
  EnabledActionsDiffer,     // an action enabled in one state of a block and not in another
  RewardDiffers,            // R(s, a) differs between two states of a block
  BlockProbabilityDiffers,  // P(B | s, a) differs between two states of a block
  LabelsDiffer,             // two states of a block hold different respected labels
  BlocksCouldMerge,         // a bisimulation, but two of its blocks are bisimilar
};

// "partition shape", "enabled actions differ", ... for messages and tests.
const char* kind_name(ViolationKind kind);

// True for the kinds that show the partition is not a bisimulation (Definition 1).
bool breaks_bisimulation(ViolationKind kind);

struct Violation {
  ViolationKind kind = ViolationKind::PartitionShape;
  // Definition 1 violations: `state` is the first member of `block`, `other_state` the member
  // that differs from it. BlocksCouldMerge: the first members of `block` and `other_block`.
  std::optional<model::StateIndex> state;
  std::optional<model::StateIndex> other_state;
  std::optional<model::ActionIndex> action;
  std::optional<model::BlockIndex> block;
  // BlockProbabilityDiffers: the block the two states reach with different probabilities.
  // BlocksCouldMerge: the block bisimilar to `block`.
  std::optional<model::BlockIndex> other_block;
  std::string message;  // one sentence naming states and actions by their names
};

struct VerificationResult {
  std::optional<Violation> violation;

  [[nodiscard]] bool ok() const { return !violation.has_value(); }
};

// "block 2 {s3, s5, s8, ...}": the block's number and its first few members by name, so a
// message can be checked against the partition without looking the number up.
std::string describe_block(const model::ExplicitModel& model, const model::Partition& partition,
                           model::BlockIndex block);

}  // namespace oasis::verify
