// Property tests of the bisimulation engine against two independent references, on thousands
// of seeded random MDPs (tests/support/random_mdp.hpp): the fast refinement must return
// exactly the partition of the naive signature fixpoint, the verifier must accept it, and the
// verifier must reject every mutation of it with a genuine, correctly classified violation.

#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../../support/naive_bisimulation.hpp"
#include "../../support/random_mdp.hpp"
#include "bisim/refinement.hpp"
#include "verify/verifier.hpp"

namespace oasis {
namespace {

using model::ExplicitModel;
using model::Partition;
using model::StateIndex;
using verify::ViolationKind;

// Sanitizers make everything ~10x slower; fewer models keep that run near a minute.
#if defined(__SANITIZE_ADDRESS__)
constexpr std::uint64_t kModels = 1000;
#else
constexpr std::uint64_t kModels = 3000;
#endif

std::string where(std::uint64_t seed, std::size_t context) {
  return "seed " + std::to_string(seed) + ", context " + std::to_string(context);
}

std::vector<std::uint32_t> labels_of(const Partition& partition) {
  return {partition.block_of.begin(), partition.block_of.end()};
}

// P(block | s, a), summed here directly from the edges rather than by the verifier's code.
Rational probability_into(const ExplicitModel& model, std::size_t context,
                          const Partition& partition, StateIndex s, model::ActionIndex a,
                          model::BlockIndex block) {
  const model::TransitionMatrix& matrix = *model.contexts[context].transitions;
  Rational sum = 0;
  for (model::EdgeIndex e = matrix.edges_begin(s, a); e < matrix.edges_end(s, a); ++e) {
    if (partition.block_of[matrix.edge_target[e]] == block)
      sum += model.values[matrix.edge_probability[e]];
  }
  return sum;
}

// The verifier's claim holds: the states and blocks it names really show the violation.
void expect_genuine(const ExplicitModel& model, std::size_t context, const Partition& partition,
                    const verify::Violation& v, const std::string& label) {
  SCOPED_TRACE(label + ": " + v.message);
  if (v.kind == ViolationKind::PartitionShape) return;
  ASSERT_TRUE(v.state && v.other_state && v.block) << "violation without its states";
  const StateIndex s = *v.state;
  const StateIndex t = *v.other_state;
  ASSERT_NE(s, t);
  EXPECT_FALSE(v.message.empty());
  if (v.kind == ViolationKind::BlocksCouldMerge) {
    ASSERT_TRUE(v.other_block);
    EXPECT_EQ(partition.block_of[s], *v.block);
    EXPECT_EQ(partition.block_of[t], *v.other_block);
    EXPECT_NE(*v.block, *v.other_block);
    const Partition coarsest = test::naive_bisimulation(model, context);
    EXPECT_EQ(coarsest.block_of[s], coarsest.block_of[t]) << "the merged blocks are not bisimilar";
    return;
  }
  const model::TransitionMatrix& matrix = *model.contexts[context].transitions;
  EXPECT_EQ(partition.block_of[s], *v.block);
  EXPECT_EQ(partition.block_of[t], *v.block);
  if (v.kind == ViolationKind::RewardDiffers && !v.action) {
    // States with no enabled action differ in their state reward R(s).
    for (model::ActionIndex a = 0; a < model.num_actions(); ++a) {
      EXPECT_FALSE(matrix.enabled(s, a) || matrix.enabled(t, a));
    }
    const auto& rewards = model.contexts[context].rewards.state;
    EXPECT_NE(model.values[rewards[s]], model.values[rewards[t]]);
    return;
  }
  ASSERT_TRUE(v.action);
  const model::ActionIndex a = *v.action;
  switch (v.kind) {
    case ViolationKind::EnabledActionsDiffer:
      EXPECT_NE(matrix.enabled(s, a), matrix.enabled(t, a));
      break;
    case ViolationKind::RewardDiffers:
      EXPECT_TRUE(matrix.enabled(s, a) && matrix.enabled(t, a));
      EXPECT_NE(model.reward(context, s, a), model.reward(context, t, a));
      break;
    case ViolationKind::BlockProbabilityDiffers:
      ASSERT_TRUE(v.other_block);
      EXPECT_NE(probability_into(model, context, partition, s, a, *v.other_block),
                probability_into(model, context, partition, t, a, *v.other_block));
      break;
    default:
      FAIL() << "unexpected kind";
  }
}

// Runs `check(model, context, coarsest, random)` on every context of every model, where
// `coarsest` is the fast engine's partition after it was compared with the naive one.
template <typename Check>
void for_each_context(std::uint64_t first_seed, Check check) {
  for (std::uint64_t seed = first_seed; seed < first_seed + kModels; ++seed) {
    const ExplicitModel model = test::random_mdp(seed);
    test::TestRandom random(seed * 7919 + 1);
    for (std::size_t c = 0; c < model.contexts.size(); ++c) {
      const Partition coarsest = bisim::coarsest_bisimulation(model, c);
      check(model, c, coarsest, random, where(seed, c));
      if (::testing::Test::HasFatalFailure()) return;
    }
  }
}

TEST(BisimProperty, GeneratorMakesValidAndInterestingModels) {
  std::size_t contexts = 0;
  std::size_t merged = 0;      // coarsest bisimulation has fewer blocks than states
  std::size_t big_blocks = 0;  // some block has at least three states
  std::size_t multi_context = 0;
  std::size_t disabled = 0;  // some action disabled somewhere
  for (std::uint64_t seed = 0; seed < kModels; ++seed) {
    const ExplicitModel model = test::random_mdp(seed);
    const auto problem = model::find_structural_problem(model);
    ASSERT_FALSE(problem) << "seed " << seed << ": " << *problem;
    if (model.contexts.size() > 1) ++multi_context;
    for (std::size_t c = 0; c < model.contexts.size(); ++c) {
      ++contexts;
      const Partition naive = test::naive_bisimulation(model, c);
      if (naive.num_blocks < model.num_states()) ++merged;
      for (const auto& block : naive.blocks()) {
        if (block.size() >= 3) {
          ++big_blocks;
          break;
        }
      }
      const auto& matrix = *model.contexts[c].transitions;
      if (matrix.num_enabled_choices() < std::size_t{model.num_states()} * model.num_actions())
        ++disabled;
    }
  }
  // Guards against a generator that drifts into trivial models, where the properties below
  // would hold vacuously.
  EXPECT_GT(merged * 2, contexts) << merged << " of " << contexts;
  EXPECT_GT(big_blocks * 4, contexts) << big_blocks << " of " << contexts;
  EXPECT_GT(multi_context * 5, kModels) << multi_context;
  EXPECT_GT(disabled * 4, contexts) << disabled << " of " << contexts;
}

TEST(BisimProperty, FastEqualsNaiveAndVerifies) {
  for (std::uint64_t seed = 0; seed < kModels; ++seed) {
    const ExplicitModel model = test::random_mdp(seed);
    for (std::size_t c = 0; c < model.contexts.size(); ++c) {
      const Partition fast = bisim::coarsest_bisimulation(model, c);
      const Partition naive = test::naive_bisimulation(model, c);
      ASSERT_EQ(fast.num_blocks, naive.num_blocks) << where(seed, c);
      ASSERT_EQ(fast.block_of, naive.block_of) << where(seed, c);
      const verify::VerificationResult result = verify::verify_partition(model, c, fast);
      ASSERT_TRUE(result.ok()) << where(seed, c) << ": " << result.violation->message;
    }
  }
}

TEST(BisimProperty, MergingTwoBlocksBreaksBisimulation) {
  // Any bisimulation is finer than the coarsest, so a coarser partition is never one.
  for_each_context(0, [](const ExplicitModel& model, std::size_t c, const Partition& coarsest,
                         test::TestRandom& random, const std::string& label) {
    if (coarsest.num_blocks < 2) return;
    const model::BlockIndex x = random.below(coarsest.num_blocks);
    model::BlockIndex y = random.below(coarsest.num_blocks - 1);
    if (y >= x) ++y;
    std::vector<std::uint32_t> labels = labels_of(coarsest);
    for (auto& label_of_state : labels) {
      if (label_of_state == y) label_of_state = x;
    }
    const Partition merged = model::canonical_partition(labels);
    const verify::VerificationResult result = verify::verify_partition(model, c, merged);
    ASSERT_FALSE(result.ok()) << label;
    EXPECT_TRUE(verify::breaks_bisimulation(result.violation->kind))
        << label << ": " << verify::kind_name(result.violation->kind);
    expect_genuine(model, c, merged, *result.violation, label);
  });
}

TEST(BisimProperty, SplittingABlockIsRejected) {
  // A split of the coarsest bisimulation is either no bisimulation at all, or one that is not
  // the coarsest; the naive refinement started from the split tells which.
  for_each_context(0, [](const ExplicitModel& model, std::size_t c, const Partition& coarsest,
                         test::TestRandom& random, const std::string& label) {
    const auto blocks = coarsest.blocks();
    std::vector<model::BlockIndex> splittable;
    for (model::BlockIndex b = 0; b < blocks.size(); ++b) {
      if (blocks[b].size() >= 2) splittable.push_back(b);
    }
    if (splittable.empty()) return;
    const auto& members = blocks[random.pick(splittable)];
    std::vector<std::uint32_t> labels = labels_of(coarsest);
    // A random non-empty proper subset moves to a new block.
    const std::uint32_t moved = random.between(1, static_cast<std::uint32_t>(members.size()) - 1);
    std::vector<StateIndex> order = members;
    for (std::uint32_t i = 0; i < moved; ++i) {
      std::swap(order[i], order[i + random.below(static_cast<std::uint32_t>(order.size()) - i)]);
      labels[order[i]] = coarsest.num_blocks;
    }
    const Partition split = model::canonical_partition(labels);
    const verify::VerificationResult result = verify::verify_partition(model, c, split);
    ASSERT_FALSE(result.ok()) << label;
    const bool still_bisimulation =
        test::naive_bisimulation(model, c, labels).block_of == split.block_of;
    if (still_bisimulation) {
      EXPECT_EQ(result.violation->kind, ViolationKind::BlocksCouldMerge)
          << label << ": " << result.violation->message;
    } else {
      EXPECT_TRUE(verify::breaks_bisimulation(result.violation->kind))
          << label << ": " << result.violation->message;
    }
    expect_genuine(model, c, split, *result.violation, label);
  });
}

TEST(BisimProperty, MovingAStateBreaksBisimulation) {
  // A state in the same block as a state it is not bisimilar to: never a bisimulation.
  for_each_context(0, [](const ExplicitModel& model, std::size_t c, const Partition& coarsest,
                         test::TestRandom& random, const std::string& label) {
    if (coarsest.num_blocks < 2) return;
    const StateIndex s = random.below(coarsest.num_states());
    model::BlockIndex to = random.below(coarsest.num_blocks - 1);
    if (to >= coarsest.block_of[s]) ++to;
    std::vector<std::uint32_t> labels = labels_of(coarsest);
    labels[s] = to;
    const Partition moved = model::canonical_partition(labels);  // drops a block left empty
    const verify::VerificationResult result = verify::verify_partition(model, c, moved);
    ASSERT_FALSE(result.ok()) << label;
    EXPECT_TRUE(verify::breaks_bisimulation(result.violation->kind)) << label;
    expect_genuine(model, c, moved, *result.violation, label);
  });
}

TEST(BisimProperty, AllSingletonsIsABisimulationButRarelyTheCoarsest) {
  for_each_context(0, [](const ExplicitModel& model, std::size_t c, const Partition& coarsest,
                         test::TestRandom&, const std::string& label) {
    std::vector<std::uint32_t> labels(model.num_states());
    for (StateIndex s = 0; s < model.num_states(); ++s)
      labels[s] = s;
    const Partition singletons = model::canonical_partition(labels);
    const verify::VerificationResult result = verify::verify_partition(model, c, singletons);
    if (coarsest.num_blocks == model.num_states()) {
      EXPECT_TRUE(result.ok()) << label;
      return;
    }
    ASSERT_FALSE(result.ok()) << label;
    EXPECT_EQ(result.violation->kind, ViolationKind::BlocksCouldMerge) << label;
    expect_genuine(model, c, singletons, *result.violation, label);
  });
}

TEST(BisimProperty, MalformedPartitionsAreRejected) {
  for_each_context(0, [](const ExplicitModel& model, std::size_t c, const Partition& coarsest,
                         test::TestRandom& random, const std::string& label) {
    Partition shorter = coarsest;
    shorter.block_of.pop_back();
    Partition out_of_range = coarsest;
    out_of_range.block_of[random.below(coarsest.num_states())] = coarsest.num_blocks;
    Partition empty_block = coarsest;
    ++empty_block.num_blocks;
    for (const Partition* bad : {&shorter, &out_of_range, &empty_block}) {
      const verify::VerificationResult result = verify::verify_partition(model, c, *bad);
      ASSERT_FALSE(result.ok()) << label;
      EXPECT_EQ(result.violation->kind, ViolationKind::PartitionShape) << label;
    }
  });
}

TEST(BisimProperty, AnyNumberingOfTheCoarsestIsAccepted) {
  // The verifier checks the partition, not its numbering: blocks in reverse order pass too.
  for_each_context(0, [](const ExplicitModel& model, std::size_t c, const Partition& coarsest,
                         test::TestRandom&, const std::string& label) {
    Partition reversed = coarsest;
    for (auto& block : reversed.block_of)
      block = coarsest.num_blocks - 1 - block;
    const verify::VerificationResult result = verify::verify_partition(model, c, reversed);
    EXPECT_TRUE(result.ok()) << label << ": " << result.violation->message;
  });
}

}  // namespace
}  // namespace oasis
