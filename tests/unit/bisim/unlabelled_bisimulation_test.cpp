// Storm's MDP semantics (`quotient --choices unlabelled`): the signature-refinement engine
// (bisim/unlabelled_refinement.hpp) against the verifier's independent check on seeded random
// MDPs, the relation to Definition 1's, and small models worked out by hand.

#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../../support/random_mdp.hpp"
#include "bisim/refinement.hpp"
#include "verify/verifier.hpp"

namespace oasis {
namespace {

using model::ExplicitModel;
using model::Partition;

#if defined(__SANITIZE_ADDRESS__)
constexpr std::uint64_t kModels = 300;
#else
constexpr std::uint64_t kModels = 1500;
#endif

Partition unlabelled(const ExplicitModel& model, std::size_t context,
                     std::vector<std::uint32_t> label_class = {}) {
  bisim::RefinementOptions options;
  options.unlabelled_choices = true;
  options.label_class = std::move(label_class);
  return bisim::coarsest_bisimulation(model, context, options);
}

// Every block of `finer` lies inside one block of `coarser`.
bool refines(const Partition& finer, const Partition& coarser) {
  std::vector<std::int64_t> image(finer.num_blocks, -1);
  for (std::size_t s = 0; s < finer.block_of.size(); ++s) {
    std::int64_t& target = image[finer.block_of[s]];
    if (target == -1) target = coarser.block_of[s];
    if (target != coarser.block_of[s]) return false;
  }
  return true;
}

TEST(UnlabelledBisimulation, RandomModelsPassTheIndependentCheckAndAreCoarserThanDefinitionOne) {
  std::uint64_t strictly_coarser = 0;
  for (std::uint64_t seed = 1; seed <= kModels; ++seed) {
    const ExplicitModel model = test::random_mdp(seed);
    for (std::size_t c = 0; c < model.contexts.size(); ++c) {
      const Partition storm = unlabelled(model, c);
      const auto verdict = verify::verify_partition(model, c, storm, {}, true);
      ASSERT_TRUE(verdict.ok()) << "seed " << seed << ": " << verdict.violation->message;
      // Matching choices action by action matches them as sets: Definition 1's bisimulation
      // is an unlabelled one, so the unlabelled coarsest is at least as coarse.
      const Partition labelled = bisim::coarsest_bisimulation(model, c);
      ASSERT_TRUE(refines(labelled, storm)) << "seed " << seed;
      strictly_coarser += storm.num_blocks < labelled.num_blocks ? 1 : 0;
    }
  }
  // The property would hold vacuously if the two never differed.
  EXPECT_GT(strictly_coarser, 0U);
}

TEST(UnlabelledBisimulation, TheCheckRejectsAMergeAndASplit) {
  for (std::uint64_t seed = 1; seed <= 200; ++seed) {
    const ExplicitModel model = test::random_mdp(seed);
    const Partition storm = unlabelled(model, 0);
    if (storm.num_blocks >= 2) {
      std::vector<std::uint32_t> merged(storm.block_of.begin(), storm.block_of.end());
      for (std::uint32_t& b : merged)
        b = b == 1 ? 0 : b;
      EXPECT_FALSE(
          verify::verify_partition(model, 0, model::canonical_partition(merged), {}, true).ok())
          << "seed " << seed;
    }
    // Splitting a state off a block: either no longer a bisimulation (a predecessor now
    // reaches the two halves differently) or one that is not the coarsest.
    const auto blocks = storm.blocks();
    for (const auto& members : blocks) {
      if (members.size() < 2) continue;
      std::vector<std::uint32_t> split(storm.block_of.begin(), storm.block_of.end());
      split[members.back()] = storm.num_blocks;
      const auto verdict =
          verify::verify_partition(model, 0, model::canonical_partition(split), {}, true);
      ASSERT_FALSE(verdict.ok()) << "seed " << seed;
      const verify::ViolationKind kind = verdict.violation->kind;
      EXPECT_TRUE(kind == verify::ViolationKind::BlocksCouldMerge ||
                  kind == verify::ViolationKind::BlockProbabilityDiffers)
          << "seed " << seed << ": " << verdict.violation->message;
      break;
    }
  }
}

// s0 and s1 reach the goal g with the same two distributions, under swapped action names:
// Storm's semantics merges them, Definition 1 does not.
ExplicitModel swapped_actions() {
  ExplicitModel model;
  model.name = "swapped";
  model.states.size = 4;
  model.states.names = {"s0", "s1", "g", "h"};
  model.actions = {"a", "b"};
  model::TransitionBuilder builder(4, 2);
  const ValueId half = model.values.intern(Rational(1, 2));
  builder.add(0, 0, 2, RationalPool::kOne);
  builder.add(0, 1, 2, half);
  builder.add(0, 1, 3, half);
  builder.add(1, 1, 2, RationalPool::kOne);
  builder.add(1, 0, 2, half);
  builder.add(1, 0, 3, half);
  builder.add(2, 0, 2, RationalPool::kOne);
  builder.add(3, 0, 3, RationalPool::kOne);
  model::Context context;
  context.name = "default";
  context.transitions =
      std::make_shared<const model::TransitionMatrix>(builder.finish(model.values));
  context.rewards.state = {RationalPool::kZero, RationalPool::kZero, RationalPool::kOne,
                           RationalPool::kZero};
  model.contexts.push_back(std::move(context));
  return model;
}

TEST(UnlabelledBisimulation, SwappedActionNamesMergeOnlyWithoutLabels) {
  const ExplicitModel model = swapped_actions();
  const Partition storm = unlabelled(model, 0);
  EXPECT_EQ(storm.num_blocks, 3U);
  EXPECT_EQ(storm.block_of[0], storm.block_of[1]);
  EXPECT_EQ(bisim::coarsest_bisimulation(model, 0).num_blocks, 4U);
  // The verifier's Definition 1 check refuses Storm's partition; its unlabelled check takes it.
  EXPECT_FALSE(verify::verify_partition(model, 0, storm).ok());
  EXPECT_TRUE(verify::verify_partition(model, 0, storm, {}, true).ok());
  // Respected labels still keep states apart.
  EXPECT_EQ(unlabelled(model, 0, {0, 1, 2, 3}).num_blocks, 4U);
}

// The model restricted to its first action, in its first context: a Markov chain (where
// that action is enabled).
ExplicitModel first_action_only(const ExplicitModel& model) {
  ExplicitModel chain;
  chain.name = model.name;
  chain.states = model.states;
  chain.actions = {model.actions.at(0)};
  chain.values = model.values;
  const model::TransitionMatrix& full = *model.contexts.at(0).transitions;
  model::TransitionBuilder builder(full.num_states, 1);
  model::RewardTable rewards;
  rewards.state = model.contexts[0].rewards.state;
  for (model::StateIndex s = 0; s < full.num_states; ++s) {
    for (model::EdgeIndex e = full.edges_begin(s, 0); e < full.edges_end(s, 0); ++e)
      builder.add(s, 0, full.edge_target[e], full.edge_probability[e]);
    if (!model.contexts[0].rewards.choice.empty())
      rewards.choice.push_back(model.contexts[0].rewards.choice[full.choice(s, 0)]);
  }
  chain.contexts.push_back(
      {"default", std::make_shared<const model::TransitionMatrix>(builder.finish(chain.values)),
       rewards});
  return chain;
}

TEST(UnlabelledBisimulation, AMarkovChainGetsTheSamePartitionEitherWay) {
  for (std::uint64_t seed = 1; seed <= 500; ++seed) {
    const ExplicitModel chain = first_action_only(test::random_mdp(seed));
    EXPECT_EQ(unlabelled(chain, 0).block_of, bisim::coarsest_bisimulation(chain, 0).block_of)
        << "seed " << seed;
  }
}

}  // namespace
}  // namespace oasis
