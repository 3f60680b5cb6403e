// Runtime tests: CatalogView validation and the Online Attention Switching filter on a
// hand-built catalog of the paper's discrete example (specs/discrete_tracking.oasis).
// Links only oasis_runtime and GTest, compiled as C++17.
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "oasis/rt/attention_filter.hpp"
#include "oasis/rt/catalog_validation.hpp"
#include "oasis/rt/catalog_view.hpp"
#include "oasis/rt/hedged_filter.hpp"

namespace {

using oasis::rt::AbstractionView;
using oasis::rt::AttentionFilter;
using oasis::rt::CatalogView;
using oasis::rt::FilterMode;
using oasis::rt::FilterOptions;
using oasis::rt::FixedWorkspace;
using oasis::rt::HedgedFilter;
using oasis::rt::HedgeOptions;
using oasis::rt::kNoAction;
using oasis::rt::ObservationKind;
using oasis::rt::RewardSource;
using oasis::rt::StepStatus;
using oasis::rt::TieRule;
using oasis::rt::validate;

constexpr std::uint32_t kS1 = 0, kS2 = 1, kS3 = 2;
constexpr std::uint32_t kL = 0, kR = 1;
constexpr std::uint32_t kAtS3 = 0, kAtS1 = 1;  // abstraction indices (spec order)

// The discrete example, built by hand. Abstraction 0 (object_at_s3): {s1,s2} -> 0 (reward 0),
// {s3} -> 1 (reward 1). Abstraction 1 (object_at_s1): {s1} -> 0 (reward 1), {s2,s3} -> 1
// (reward 0). Switching 'stay 0.8', uniform prior. Values: discount 0.9, V = 10 in the
// rewarded block and 4.5 / 0.55 in the other.
struct DiscreteExample {
  const char* action_names[2] = {"L", "R"};
  const char* state_names[3] = {"s1", "s2", "s3"};
  double switching[4] = {0.8, 0.2, 0.2, 0.8};
  double prior[2] = {0.5, 0.5};

  // object_at_s3
  std::uint32_t a0_block_of[3] = {0, 0, 1};
  double a0_block_reward[2] = {0.0, 1.0};
  // rows (z, a): (0,L) -> {0:1}; (0,R) -> {0:.5, 1:.5}; (1,L) -> {0:1}; (1,R) -> {1:1}
  std::uint32_t a0_begin[5] = {0, 1, 3, 4, 5};
  std::uint32_t a0_target[5] = {0, 0, 1, 0, 1};
  double a0_prob[5] = {1.0, 0.5, 0.5, 1.0, 1.0};
  double a0_reward[4] = {0.0, 0.0, 1.0, 1.0};
  std::uint32_t a0_policy[2] = {kR, kR};
  double a0_value[2] = {4.5 / 0.55, 10.0};

  // object_at_s1
  std::uint32_t a1_block_of[3] = {0, 1, 1};
  double a1_block_reward[2] = {1.0, 0.0};
  // (0,L) -> {0:1}; (0,R) -> {1:1}; (1,L) -> {0:.5, 1:.5}; (1,R) -> {1:1}
  std::uint32_t a1_begin[5] = {0, 1, 2, 4, 5};
  std::uint32_t a1_target[5] = {0, 1, 0, 1, 1};
  double a1_prob[5] = {1.0, 1.0, 0.5, 0.5, 1.0};
  double a1_reward[4] = {1.0, 1.0, 0.0, 0.0};
  std::uint32_t a1_policy[2] = {kL, kL};
  double a1_value[2] = {10.0, 4.5 / 0.55};

  // Full-state model from the spec (same in both contexts), rows (s, a).
  std::uint32_t st_begin[7] = {0, 1, 3, 5, 7, 9, 10};
  std::uint32_t st_target[10] = {kS1, kS2, kS3, kS1, kS2, kS2, kS3, kS1, kS2, kS3};
  double st_prob[10] = {1.0, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 1.0};

  AbstractionView abstractions[2];
  CatalogView view;

  explicit DiscreteExample(bool robust = false, double p_correct = 0.7) {
    AbstractionView& a0 = abstractions[0];
    a0.context = "object_at_s3";
    a0.num_blocks = 2;
    a0.block_of = a0_block_of;
    a0.block_reward = a0_block_reward;
    a0.quotient = {a0_begin, a0_target, a0_prob, 5};
    a0.reward = a0_reward;
    a0.policy = a0_policy;
    a0.value = a0_value;
    AbstractionView& a1 = abstractions[1];
    a1.context = "object_at_s1";
    a1.num_blocks = 2;
    a1.block_of = a1_block_of;
    a1.block_reward = a1_block_reward;
    a1.quotient = {a1_begin, a1_target, a1_prob, 5};
    a1.reward = a1_reward;
    a1.policy = a1_policy;
    a1.value = a1_value;

    view.name = "discrete_tracking";
    view.spec_hash = 0x1234;
    view.compiler_version = "test";
    view.num_states = 3;
    view.num_actions = 2;
    view.action_names = action_names;
    view.state_names = state_names;
    view.num_abstractions = 2;
    view.switching = switching;
    view.prior = prior;
    view.abstractions = abstractions;
    if (robust) {
      for (AbstractionView& a : abstractions)
        a.state_transitions = {st_begin, st_target, st_prob, 10};
      view.observation.kind = ObservationKind::kSymmetric;
      view.observation.p_correct = p_correct;
    }
  }
  DiscreteExample(const DiscreteExample&) = delete;
  DiscreteExample& operator=(const DiscreteExample&) = delete;
};

constexpr double kEps = 1e-12;

bool belief_is_distribution(const AttentionFilter& f, std::uint32_t n) {
  double sum = 0.0;
  for (std::uint32_t i = 0; i < n; ++i) {
    const double b = f.belief(i);
    if (!std::isfinite(b) || b < 0.0) return false;
    sum += b;
  }
  return std::fabs(sum - 1.0) < 1e-9;
}

// ---------------------------------------------------------------- validate()

TEST(RuntimeCatalog, DiscreteExampleIsValid) {
  DiscreteExample ex;
  std::string why;
  EXPECT_TRUE(validate(ex.view, &why)) << why;
  DiscreteExample robust(true);
  EXPECT_TRUE(validate(robust.view, &why)) << why;
  EXPECT_TRUE(robust.view.has_robust_section());
  EXPECT_FALSE(ex.view.has_robust_section());
}

TEST(RuntimeCatalog, RejectsBadSizes) {
  std::string why;
  {
    DiscreteExample ex;
    ex.view.num_states = 0;
    EXPECT_FALSE(validate(ex.view, &why));
    EXPECT_NE(why.find("num_states"), std::string::npos) << why;
  }
  {
    DiscreteExample ex;
    ex.view.num_abstractions = 0;
    EXPECT_FALSE(validate(ex.view, &why));
  }
  {
    DiscreteExample ex;
    ex.view.format = oasis::rt::kCatalogFormat + 1;
    EXPECT_FALSE(validate(ex.view, &why));
    EXPECT_NE(why.find("format"), std::string::npos) << why;
  }
  {
    DiscreteExample ex;  // CSR end does not match num_edges
    ex.abstractions[0].quotient.num_edges = 4;
    EXPECT_FALSE(validate(ex.view, &why));
  }
  {
    DiscreteExample ex;  // choice_begin decreasing
    ex.a1_begin[2] = 0;
    EXPECT_FALSE(validate(ex.view, &why));
  }
  {
    DiscreteExample ex;  // a block with no state
    ex.abstractions[0].num_blocks = 3;
    EXPECT_FALSE(validate(ex.view, &why));
  }
  {
    DiscreteExample ex;
    ex.view.abstractions = nullptr;
    EXPECT_FALSE(validate(ex.view, &why));
  }
  {
    DiscreteExample ex;  // robust transitions without an observation model
    ex.abstractions[0].state_transitions = {ex.st_begin, ex.st_target, ex.st_prob, 10};
    EXPECT_FALSE(validate(ex.view, &why));
  }
  {
    DiscreteExample ex(true);  // observation model without transitions for one abstraction
    ex.abstractions[1].state_transitions = {};
    EXPECT_FALSE(validate(ex.view, &why));
  }
}

TEST(RuntimeCatalog, RejectsOutOfRangeIndices) {
  std::string why;
  {
    DiscreteExample ex;
    ex.a0_block_of[2] = 2;
    EXPECT_FALSE(validate(ex.view, &why));
    EXPECT_NE(why.find("block_of"), std::string::npos) << why;
  }
  {
    DiscreteExample ex;
    ex.a1_target[3] = 7;
    EXPECT_FALSE(validate(ex.view, &why));
    EXPECT_NE(why.find("target"), std::string::npos) << why;
  }
  {
    DiscreteExample ex;
    ex.a0_policy[1] = 5;
    EXPECT_FALSE(validate(ex.view, &why));
  }
  {
    DiscreteExample ex;
    ex.a0_policy[0] = kNoAction;  // actions are enabled there
    EXPECT_FALSE(validate(ex.view, &why));
  }
  {
    DiscreteExample ex(true);
    ex.st_target[9] = 3;
    EXPECT_FALSE(validate(ex.view, &why));
  }
}

TEST(RuntimeCatalog, RejectsBadProbabilities) {
  std::string why;
  {
    DiscreteExample ex;
    ex.switching[1] = 0.3;  // row 0 sums to 1.1
    EXPECT_FALSE(validate(ex.view, &why));
    EXPECT_NE(why.find("switching"), std::string::npos) << why;
  }
  {
    DiscreteExample ex;
    ex.prior[0] = 0.6;
    EXPECT_FALSE(validate(ex.view, &why));
  }
  {
    DiscreteExample ex;
    ex.a0_prob[1] = 0.4;  // (0,R) sums to 0.9
    EXPECT_FALSE(validate(ex.view, &why));
  }
  {
    DiscreteExample ex;
    ex.a0_prob[1] = -0.5;
    ex.a0_prob[2] = 1.5;
    EXPECT_FALSE(validate(ex.view, &why));
  }
  {
    DiscreteExample ex(true, 1.5);
    EXPECT_FALSE(validate(ex.view, &why));
  }
}

TEST(RuntimeCatalog, RejectsNaN) {
  const double nan = std::nan("");
  std::string why;
  {
    DiscreteExample ex;
    ex.switching[0] = nan;
    EXPECT_FALSE(validate(ex.view, &why));
  }
  {
    DiscreteExample ex;
    ex.prior[1] = nan;
    EXPECT_FALSE(validate(ex.view, &why));
  }
  {
    DiscreteExample ex;
    ex.a1_block_reward[0] = nan;
    EXPECT_FALSE(validate(ex.view, &why));
  }
  {
    DiscreteExample ex;
    ex.a1_prob[0] = nan;
    EXPECT_FALSE(validate(ex.view, &why));
  }
  {
    DiscreteExample ex;
    ex.a0_value[0] = std::numeric_limits<double>::infinity();
    EXPECT_FALSE(validate(ex.view, &why));
  }
}

// Corrupt one array element at a time (the arrays keep the lengths the view states, as a
// loader guarantees) and check that validate() never reads out of bounds (ASan) and that
// whatever it accepts runs through the filter without leaving a distribution.
TEST(RuntimeCatalog, CorruptedArraysAreRejectedOrHarmless) {
  const std::uint32_t index_pool[] = {0, 1, 2, 3, 4, 5, 7, 10, 11, 0xFFFFFFFFu};
  const double value_pool[] = {std::nan(""), -1.0, 0.0, 0.25,
                               0.5,          1.0,  2.0, std::numeric_limits<double>::infinity()};
  std::uint64_t rng = 12345;
  auto next = [&rng] {
    rng = rng * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<std::uint32_t>(rng >> 33);
  };
  int accepted = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    DiscreteExample ex(trial % 2 == 0);
    std::uint32_t* ints[] = {ex.a0_block_of, ex.a1_block_of, ex.a0_begin,  ex.a1_begin,
                             ex.a0_target,   ex.a1_target,   ex.a0_policy, ex.a1_policy,
                             ex.st_begin,    ex.st_target};
    const std::uint32_t int_sizes[] = {3, 3, 5, 5, 5, 5, 2, 2, 7, 10};
    double* doubles[] = {ex.switching, ex.prior,           ex.a0_prob,
                         ex.a1_prob,   ex.a0_block_reward, ex.st_prob};
    const std::uint32_t double_sizes[] = {4, 2, 5, 5, 2, 10};
    for (int k = 0; k < 1 + trial % 3; ++k) {
      if (next() % 2 == 0) {
        const std::uint32_t which = next() % 10;
        ints[which][next() % int_sizes[which]] = index_pool[next() % 10];
      } else {
        const std::uint32_t which = next() % 6;
        doubles[which][next() % double_sizes[which]] = value_pool[next() % 8];
      }
    }
    if (!validate(ex.view)) continue;
    ++accepted;
    for (FilterMode mode : {FilterMode::kPaper, FilterMode::kJoint}) {
      FilterOptions options;
      options.mode = mode;
      FixedWorkspace<2, 3> ws;
      AttentionFilter f(ex.view, options, ws);
      if (!f.ok()) continue;
      f.start(next() % 3);
      for (int s = 0; s < 10; ++s) {
        f.step(next() % 3, (next() % 3) * 0.5, f.action() == kNoAction ? 0 : f.action());
        ASSERT_TRUE(belief_is_distribution(f, 2));
      }
    }
  }
  EXPECT_GT(accepted, 0);  // some mutations are harmless (e.g. a value rewritten to itself)
}

// ---------------------------------------------------------------- paper mode

TEST(RuntimeFilter, StartsAtPriorWithLowestTiedIndex) {
  DiscreteExample ex;
  FixedWorkspace<2> ws;
  AttentionFilter f(ex.view, FilterOptions{}, ws);
  ASSERT_TRUE(f.ok());
  EXPECT_DOUBLE_EQ(f.belief(0), 0.5);
  EXPECT_DOUBLE_EQ(f.belief(1), 0.5);
  EXPECT_EQ(f.ml_abstraction(), 0u);
  EXPECT_EQ(f.action(), kNoAction);  // no state observed yet
  EXPECT_EQ(f.start(kS2), StepStatus::kOk);
  EXPECT_EQ(f.action(), kR);  // pi^0({s1,s2}) = R
}

// Hand computation, stay 0.8, prior (1/2, 1/2):
//  t=1 s3 r=1: predicted (.5,.5); likelihoods (1, 0)        -> (1, 0)
//  t=2 s2 r=0: predicted (.8,.2); likelihoods (1, 1)        -> (.8, .2)
//  t=3 s1 r=0: predicted (.68,.32); likelihoods (1, 0)      -> (1, 0)
//  t=4 s2 r=0: predicted (.8,.2); both match                -> (.8, .2)
//  t=5 s2 r=0: predicted (.68,.32); both match              -> (.68, .32)
//  t=6 s1 r=1: predicted (.608,.392); likelihoods (0, 1)    -> (0, 1)  switch to object_at_s1
TEST(RuntimeFilter, BeliefMatchesHandComputation) {
  DiscreteExample ex;
  std::vector<double> buffer(AttentionFilter::workspace_size(ex.view, FilterOptions{}));
  AttentionFilter f(ex.view, FilterOptions{}, buffer.data(), buffer.size());
  ASSERT_TRUE(f.ok());
  ASSERT_EQ(f.start(kS2), StepStatus::kOk);

  struct Expect {
    std::uint32_t state;
    double reward;
    double b0;
    std::uint32_t ml;
    std::uint32_t action;
  };
  const Expect steps[] = {
      {kS3, 1.0, 1.0, kAtS3, kR}, {kS2, 0.0, 0.8, kAtS3, kR},  {kS1, 0.0, 1.0, kAtS3, kR},
      {kS2, 0.0, 0.8, kAtS3, kR}, {kS2, 0.0, 0.68, kAtS3, kR}, {kS1, 1.0, 0.0, kAtS1, kL},
  };
  int t = 1;
  for (const Expect& e : steps) {
    const std::uint32_t a = f.action();
    EXPECT_EQ(f.step(e.state, e.reward, a), StepStatus::kOk) << "t=" << t;
    EXPECT_NEAR(f.belief(0), e.b0, kEps) << "t=" << t;
    EXPECT_NEAR(f.belief(1), 1.0 - e.b0, kEps) << "t=" << t;
    EXPECT_EQ(f.ml_abstraction(), e.ml) << "t=" << t;
    EXPECT_EQ(f.action(), e.action) << "t=" << t;
    ++t;
  }
  EXPECT_EQ(f.abstract_state(), 0u);  // s1 is block {s1} of object_at_s1
}

TEST(RuntimeFilter, SwitchesWhenOnlyTheOtherAbstractionExplainsTheReward) {
  DiscreteExample ex;
  FixedWorkspace<2> ws;
  AttentionFilter f(ex.view, FilterOptions{}, ws);
  f.start(kS3);
  // Confirm object_at_s3 several times: reward 1 in s3.
  for (int k = 0; k < 5; ++k)
    EXPECT_EQ(f.step(kS3, 1.0, kR), StepStatus::kOk);
  EXPECT_EQ(f.ml_abstraction(), kAtS3);
  EXPECT_NEAR(f.belief(kAtS3), 1.0, kEps);
  // Reward 0 in s3: only object_at_s1 explains it ({s2,s3} has reward 0 there).
  EXPECT_EQ(f.step(kS3, 0.0, kR), StepStatus::kOk);
  EXPECT_EQ(f.ml_abstraction(), kAtS1);
  EXPECT_NEAR(f.belief(kAtS1), 1.0, kEps);
  EXPECT_EQ(f.action(), kL);
}

TEST(RuntimeFilter, ObservationsBothExplainLeaveOnlyTheSwitchingModel) {
  DiscreteExample ex;
  FixedWorkspace<2> ws;
  AttentionFilter f(ex.view, FilterOptions{}, ws);
  f.start(kS2);
  f.step(kS3, 1.0, kR);  // (1, 0)
  // s2 with reward 0 is explained by both: the belief relaxes towards (1/2, 1/2):
  // b0 <- 0.8 b0 + 0.2 (1 - b0) = 0.2 + 0.6 b0.
  double b0 = 1.0;
  for (int k = 0; k < 20; ++k) {
    f.step(kS2, 0.0, kL);
    b0 = 0.2 + 0.6 * b0;
    EXPECT_NEAR(f.belief(0), b0, 1e-12);
  }
  EXPECT_EQ(f.ml_abstraction(), kAtS3);  // never below 1/2, so no switch
}

// ---------------------------------------------------------------- tie rules

TEST(RuntimeFilter, KeepTieRuleKeepsCurrentAbstraction) {
  DiscreteExample ex;
  ex.switching[0] = ex.switching[1] = ex.switching[2] = ex.switching[3] = 0.5;  // model (ii)
  FixedWorkspace<2> ws;
  FilterOptions options;
  options.tie_rule = TieRule::kKeep;
  AttentionFilter f(ex.view, options, ws);
  f.start(kS2);
  f.step(kS1, 1.0, kL);  // only object_at_s1 -> (0, 1)
  EXPECT_EQ(f.ml_abstraction(), kAtS1);
  // With stay 0.5 and an uninformative observation the belief is (1/2, 1/2): a tie.
  for (int k = 0; k < 10; ++k) {
    f.step(kS2, 0.0, kL);
    EXPECT_NEAR(f.belief(0), 0.5, kEps);
    EXPECT_EQ(f.ml_abstraction(), kAtS1) << "Keep must not move on a tie";
  }
  // Reset: no current abstraction, the lowest tied index wins.
  f.reset();
  EXPECT_EQ(f.ml_abstraction(), 0u);
}

std::vector<std::uint32_t> random_tie_choices(std::uint64_t seed, int steps) {
  DiscreteExample ex;
  FixedWorkspace<2> ws;
  FilterOptions options;
  options.tie_rule = TieRule::kRandom;
  options.seed = seed;
  AttentionFilter f(ex.view, options, ws);
  f.start(kS2);
  std::vector<std::uint32_t> choices;
  // Uniform prior, s2 with reward 0 explained by both: every step stays at (1/2, 1/2).
  for (int k = 0; k < steps; ++k) {
    f.step(kS2, 0.0, kL);
    choices.push_back(f.ml_abstraction());
  }
  return choices;
}

TEST(RuntimeFilter, RandomTieRuleIsReproduciblePerSeed) {
  const auto a = random_tie_choices(42, 64);
  const auto b = random_tie_choices(42, 64);
  const auto c = random_tie_choices(43, 64);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
  int zeros = 0;
  for (std::uint32_t i : a)
    zeros += (i == 0);
  EXPECT_GT(zeros, 10);  // both abstractions are picked
  EXPECT_LT(zeros, 54);
  // Pinned values for seed 42: SplitMix64 is fully specified, so these hold on every platform
  // (the first draw is spent on the tied prior at start(), the next eight on the steps).
  const std::vector<std::uint32_t> pinned = {1, 0, 0, 0, 0, 1, 0, 1};
  EXPECT_EQ(std::vector<std::uint32_t>(a.begin(), a.begin() + 8), pinned);
}

TEST(RuntimeFilter, RandomTieRuleFollowsAClearMaximum) {
  DiscreteExample ex;
  FixedWorkspace<2> ws;
  FilterOptions options;
  options.tie_rule = TieRule::kRandom;
  AttentionFilter f(ex.view, options, ws);
  f.start(kS3);
  for (int k = 0; k < 10; ++k) {
    f.step(kS3, 1.0, kR);
    EXPECT_EQ(f.ml_abstraction(), kAtS3);
  }
}

// ---------------------------------------------------------------- zero likelihood

// Reward 0.5 matches no abstraction anywhere: every likelihood is 0.
TEST(RuntimeFilter, ZeroLikelihoodWithoutGuardResetsToPrior) {
  DiscreteExample ex;
  ex.prior[0] = 0.25;
  ex.prior[1] = 0.75;
  FixedWorkspace<2> ws;
  AttentionFilter f(ex.view, FilterOptions{}, ws);
  f.start(kS3);
  f.step(kS3, 1.0, kR);  // (1, 0)
  EXPECT_EQ(f.step(kS3, 0.5, kR), StepStatus::kZeroLikelihood);
  EXPECT_DOUBLE_EQ(f.belief(0), 0.25);
  EXPECT_DOUBLE_EQ(f.belief(1), 0.75);
  EXPECT_EQ(f.ml_abstraction(), kAtS1);
}

TEST(RuntimeFilter, ZeroLikelihoodGuardKeepsPredictedBelief) {
  DiscreteExample ex;
  FixedWorkspace<2> ws;
  FilterOptions options;
  options.zero_likelihood_guard = true;
  AttentionFilter f(ex.view, options, ws);
  f.start(kS3);
  f.step(kS3, 1.0, kR);  // (1, 0)
  EXPECT_EQ(f.step(kS3, 0.5, kR), StepStatus::kZeroLikelihood);
  EXPECT_NEAR(f.belief(0), 0.8, kEps);  // the dynamics update alone
  EXPECT_EQ(f.ml_abstraction(), kAtS3);
}

TEST(RuntimeFilter, NeverProducesNaN) {
  const double nan = std::nan("");
  const double inf = std::numeric_limits<double>::infinity();
  for (bool guard : {false, true}) {
    for (double eps : {0.0, 0.1}) {
      DiscreteExample ex;
      FixedWorkspace<2> ws;
      FilterOptions options;
      options.zero_likelihood_guard = guard;
      options.detection_epsilon = eps;
      AttentionFilter f(ex.view, options, ws);
      f.start(kS1);
      const double rewards[] = {nan, 1.0, inf, -inf, 0.5, 0.0, nan, 1e300};
      std::uint32_t state = 0;
      for (int k = 0; k < 200; ++k) {
        const StepStatus st = f.step(state, rewards[k % 8], f.action());
        EXPECT_TRUE(st == StepStatus::kOk || st == StepStatus::kZeroLikelihood);
        ASSERT_TRUE(belief_is_distribution(f, 2)) << "guard=" << guard << " k=" << k;
        state = (state + 1) % 3;
      }
    }
  }
}

TEST(RuntimeFilter, RejectsOutOfRangeInputWithoutChange) {
  DiscreteExample ex;
  FixedWorkspace<2> ws;
  AttentionFilter f(ex.view, FilterOptions{}, ws);
  f.start(kS3);
  f.step(kS3, 1.0, kR);
  EXPECT_EQ(f.step(3, 1.0, kR), StepStatus::kBadState);
  EXPECT_EQ(f.step(0xFFFFFFFFu, 1.0, kR), StepStatus::kBadState);
  EXPECT_EQ(f.step(kS1, 1.0, 2), StepStatus::kBadAction);
  EXPECT_EQ(f.start(9), StepStatus::kBadState);
  EXPECT_DOUBLE_EQ(f.belief(0), 1.0);
  EXPECT_EQ(f.policy_state(), kS3);
}

TEST(RuntimeFilter, ConstructionErrors) {
  DiscreteExample ex;
  double small[1];
  AttentionFilter too_small(ex.view, FilterOptions{}, small, 1);
  EXPECT_FALSE(too_small.ok());
  EXPECT_EQ(too_small.error(), oasis::rt::FilterError::kWorkspaceTooSmall);
  EXPECT_EQ(too_small.step(kS1, 0.0, kL), StepStatus::kNotReady);
  EXPECT_EQ(too_small.action(), kNoAction);

  FixedWorkspace<2, 3> ws;
  FilterOptions robust;
  robust.mode = FilterMode::kJoint;
  AttentionFilter no_section(ex.view, robust, ws);
  EXPECT_EQ(no_section.error(), oasis::rt::FilterError::kNoRobustSection);
  FilterOptions noise_aware;
  noise_aware.mode = FilterMode::kNoiseAware;  // a continuous catalog's mode
  AttentionFilter wrong_kind(ex.view, noise_aware, ws);
  EXPECT_EQ(wrong_kind.error(), oasis::rt::FilterError::kWrongCatalogKind);
  EXPECT_EQ(oasis::rt::noise_model_mode(ex.view), FilterMode::kJoint);

  FilterOptions bad;
  bad.detection_epsilon = 1.0;
  AttentionFilter bad_eps(ex.view, bad, ws);
  EXPECT_EQ(bad_eps.error(), oasis::rt::FilterError::kBadOptions);
  bad.detection_epsilon = std::nan("");
  AttentionFilter nan_eps(ex.view, bad, ws);
  EXPECT_EQ(nan_eps.error(), oasis::rt::FilterError::kBadOptions);
}

// ---------------------------------------------------------------- soft detection

// epsilon = 0.1: likelihood 0.9 on a match, 0.1 otherwise.
//  t=1 s3 r=1: predicted (.5,.5) -> (.45, .05)/.5 = (.9, .1)
//  t=2 s1 r=1: predicted (.74,.26) -> (.074, .234)/.308
TEST(RuntimeFilter, SoftDetectionModel) {
  DiscreteExample ex;
  FixedWorkspace<2> ws;
  FilterOptions options;
  options.detection_epsilon = 0.1;
  AttentionFilter f(ex.view, options, ws);
  f.start(kS2);
  EXPECT_EQ(f.step(kS3, 1.0, kR), StepStatus::kOk);
  EXPECT_NEAR(f.belief(0), 0.9, kEps);
  EXPECT_EQ(f.step(kS1, 1.0, kL), StepStatus::kOk);
  EXPECT_NEAR(f.belief(0), 0.074 / 0.308, kEps);
  EXPECT_EQ(f.ml_abstraction(), kAtS1);
  // An unexplained reward no longer triggers the zero-likelihood path.
  EXPECT_EQ(f.step(kS1, 0.5, kL), StepStatus::kOk);
}

TEST(RuntimeFilter, RewardToleranceIsAbsolute) {
  DiscreteExample ex;
  FixedWorkspace<2> ws;
  AttentionFilter f(ex.view, FilterOptions{}, ws);
  f.start(kS3);
  EXPECT_EQ(f.step(kS3, 1.0 + 1e-10, kR), StepStatus::kOk);  // within 1e-9: matches
  EXPECT_NEAR(f.belief(0), 1.0, kEps);
  EXPECT_EQ(f.step(kS3, 1.0 + 1e-6, kR), StepStatus::kZeroLikelihood);  // outside
}

// ---------------------------------------------------------------- robust mode

// The robot sits in s3 with the object (object_at_s3, reward 1) and keeps pressing R (s3 -> s3
// with probability 1). One faulty observation reports s1 while the reward is still 1.
// Paper filter: s1 with reward 1 is explained only by object_at_s1, so it switches. Robust
// filter: (object_at_s1, s1) needs the robot to have reached s1 from s3 under R, which P
// forbids; (object_at_s3, s3) needs one sensor error, probability (1 - p_correct) / 2 > 0; so
// it keeps object_at_s3 and still believes the robot is in s3.
TEST(RuntimeFilter, RobustModeSurvivesOneWrongStateObservation) {
  DiscreteExample ex(true, 0.7);
  ASSERT_TRUE(validate(ex.view));

  FixedWorkspace<2> paper_ws;
  AttentionFilter paper(ex.view, FilterOptions{}, paper_ws);
  FixedWorkspace<2, 3> robust_ws;
  FilterOptions options;
  options.mode = FilterMode::kJoint;
  AttentionFilter robust(ex.view, options, robust_ws);
  ASSERT_TRUE(robust.ok());

  paper.start(kS3);
  robust.start(kS3);
  for (int k = 0; k < 5; ++k) {
    paper.step(kS3, 1.0, kR);
    robust.step(kS3, 1.0, kR);
    ASSERT_TRUE(belief_is_distribution(robust, 2));
  }
  EXPECT_EQ(paper.ml_abstraction(), kAtS3);
  EXPECT_EQ(robust.ml_abstraction(), kAtS3);
  EXPECT_NEAR(robust.joint_belief(kAtS3, kS3), 1.0, kEps);

  EXPECT_EQ(paper.step(kS1, 1.0, kR), StepStatus::kOk);
  EXPECT_EQ(robust.step(kS1, 1.0, kR), StepStatus::kOk);
  EXPECT_EQ(paper.ml_abstraction(), kAtS1) << "the paper's filter is fooled";
  EXPECT_EQ(paper.action(), kL);
  EXPECT_EQ(robust.ml_abstraction(), kAtS3) << "the robust filter is not";
  EXPECT_NEAR(robust.belief(kAtS3), 1.0, kEps);
  EXPECT_EQ(robust.policy_state(), kS3);
  EXPECT_EQ(robust.abstract_state(), 1u);
  EXPECT_EQ(robust.action(), kR);
}

// Hand computation of one robust step from the start: prior (1/2, 1/2), o_0 = s2, p = 0.7.
// start: b(i, s) = 1/2 * (.15, .7, .15).
// step a = R, o = s3, r = 1. Switching keeps (1/2 each). Move under R:
//   s1 .15 -> s2 .075, s3 .075; s2 .7 -> s2 .35, s3 .35; s3 .15 -> s3 .15
//   per abstraction (unnormalised by 1/2): s1 0, s2 .425, s3 .575.
// Weight by p(s3 | s) = (.15, .15, .7) and detection r=1: object_at_s3 only at s3,
// object_at_s1 only at s1 (which has mass 0). So all mass on (object_at_s3, s3).
TEST(RuntimeFilter, RobustStepMatchesHandComputation) {
  DiscreteExample ex(true, 0.7);
  FixedWorkspace<2, 3> ws;
  FilterOptions options;
  options.mode = FilterMode::kJoint;
  AttentionFilter f(ex.view, options, ws);
  ASSERT_EQ(f.start(kS2), StepStatus::kOk);
  EXPECT_NEAR(f.joint_belief(0, kS1), 0.075, kEps);
  EXPECT_NEAR(f.joint_belief(1, kS2), 0.35, kEps);
  EXPECT_EQ(f.policy_state(), kS2);
  EXPECT_EQ(f.step(kS3, 1.0, kR), StepStatus::kOk);
  EXPECT_NEAR(f.joint_belief(kAtS3, kS3), 1.0, kEps);
  EXPECT_NEAR(f.belief(kAtS3), 1.0, kEps);
  // Then a = L, o = s2, r = 0: switching gives (.8, .2) on s3; L from s3 -> s1 .5, s2 .5.
  // Weights p(s2 | s) = (.15, .7, .15); detection r = 0:
  //   object_at_s3 (blocks {s1,s2} reward 0): s1 yes, s2 yes -> .8*.5*.15, .8*.5*.7
  //   object_at_s1 ({s1} reward 1): s1 no, s2 yes           -> 0, .2*.5*.7
  // total = .06 + .28 + .07 = .41.
  EXPECT_EQ(f.step(kS2, 0.0, kL), StepStatus::kOk);
  EXPECT_NEAR(f.joint_belief(kAtS3, kS1), 0.06 / 0.41, kEps);
  EXPECT_NEAR(f.joint_belief(kAtS3, kS2), 0.28 / 0.41, kEps);
  EXPECT_NEAR(f.joint_belief(kAtS1, kS2), 0.07 / 0.41, kEps);
  EXPECT_NEAR(f.belief(kAtS3), 0.34 / 0.41, kEps);
  EXPECT_EQ(f.policy_state(), kS2);
}

TEST(RuntimeFilter, RobustZeroLikelihoodNeverNaN) {
  for (bool guard : {false, true}) {
    DiscreteExample ex(true, 1.0);  // a perfect sensor makes contradictions easy
    FixedWorkspace<2, 3> ws;
    FilterOptions options;
    options.mode = FilterMode::kJoint;
    options.zero_likelihood_guard = guard;
    AttentionFilter f(ex.view, options, ws);
    f.start(kS3);
    f.step(kS3, 1.0, kR);
    // s3 under R stays s3; observing s1 with a perfect sensor is impossible.
    EXPECT_EQ(f.step(kS1, 1.0, kR), StepStatus::kZeroLikelihood);
    ASSERT_TRUE(belief_is_distribution(f, 2));
    if (guard) {
      EXPECT_NEAR(f.joint_belief(kAtS3, kS3), 0.8, kEps);  // prediction kept
    } else {
      EXPECT_NEAR(f.joint_belief(kAtS3, kS1), 0.5, kEps);  // prior x p(o | s)
      EXPECT_NEAR(f.joint_belief(kAtS1, kS1), 0.5, kEps);
    }
    for (int k = 0; k < 50; ++k) {
      f.step(static_cast<std::uint32_t>(k % 3), (k % 4) * 0.5, static_cast<std::uint32_t>(k % 2));
      ASSERT_TRUE(belief_is_distribution(f, 2));
    }
  }
}

// The reward evidence of the two steps of RobustStepMatchesHandComputation: the first step's
// prediction puts no mass where object_at_s1 pays 1, the second's p(o = s2) is
//   .8*.5*.15 + .8*.5*.7 + .2*.5*.15 + .2*.5*.7 = .425, of which .41 explains r = 0.
TEST(RuntimeFilter, RewardEvidenceMatchesHandComputation) {
  DiscreteExample ex(true, 0.7);
  FixedWorkspace<2, 3> ws;
  FilterOptions options;
  options.mode = FilterMode::kJoint;
  AttentionFilter robust(ex.view, options, ws);
  robust.start(kS2);
  EXPECT_EQ(robust.reward_evidence(), 1.0);
  robust.step(kS3, 1.0, kR);
  // The prediction is .5 * (0, .425, .575) per abstraction, p(o = s3 | s) = (.15, .15, .7),
  // and only (object_at_s3, s3) pays 1: .5*.575*.7 over 2 * .5*(.425*.15 + .575*.7).
  const double observed = 0.425 * 0.15 + 0.575 * 0.7;
  EXPECT_NEAR(robust.reward_evidence(), 0.5 * 0.575 * 0.7 / observed, kEps);
  robust.step(kS2, 0.0, kL);
  EXPECT_NEAR(robust.reward_evidence(), 0.41 / 0.425, kEps);

  FixedWorkspace<2> paper_ws;
  AttentionFilter paper(ex.view, FilterOptions{}, paper_ws);
  paper.start(kS3);
  paper.step(kS3, 1.0, kR);  // only object_at_s3 pays 1 at s3; prediction (.5, .5)
  EXPECT_NEAR(paper.reward_evidence(), 0.5, kEps);
  paper.step(kS3, 0.0, kR);  // only object_at_s1 pays 0 at s3; its prediction is .2
  EXPECT_NEAR(paper.reward_evidence(), 0.2, kEps);
}

// With the reward declared to follow the observed state, the detection model is applied at
// o: at o = s2 both abstractions pay 0, so r = 0 says nothing about the context.
TEST(RuntimeFilter, RobustRewardCanFollowTheObservedState) {
  DiscreteExample ex(true, 0.7);
  ex.view.observation.reward_source = RewardSource::kObservedState;
  FixedWorkspace<2, 3> ws;
  FilterOptions options;
  options.mode = FilterMode::kJoint;
  AttentionFilter f(ex.view, options, ws);
  f.start(kS2);
  EXPECT_EQ(f.step(kS2, 0.0, kL), StepStatus::kOk);
  EXPECT_NEAR(f.reward_evidence(), 1.0, kEps);
  EXPECT_NEAR(f.belief(kAtS3), 0.5, kEps);
  // r = 1 at o = s3: only object_at_s3 pays there, whatever the true state.
  EXPECT_EQ(f.step(kS3, 1.0, kR), StepStatus::kOk);
  EXPECT_NEAR(f.belief(kAtS3), 1.0, kEps);
}

// ---------------------------------------------------------------- context evidence

// After step() gives (.8, .2), a sighting with p(seen | context) = (.1, .9):
// (.08, .18) / .26, and the ML abstraction follows it.
TEST(RuntimeFilter, WeighContextIsBayesRuleOnTheBelief) {
  DiscreteExample ex;
  FixedWorkspace<2> ws;
  AttentionFilter f(ex.view, FilterOptions{}, ws);
  f.start(kS2);
  f.step(kS3, 1.0, kR);  // (1, 0)
  f.step(kS2, 0.0, kL);  // (.8, .2)
  ASSERT_NEAR(f.belief(kAtS3), 0.8, kEps);
  const double sighting[] = {0.1, 0.9};
  EXPECT_EQ(f.weigh_context(sighting, 2), StepStatus::kOk);
  EXPECT_NEAR(f.belief(kAtS3), 0.08 / 0.26, kEps);
  EXPECT_NEAR(f.belief(kAtS1), 0.18 / 0.26, kEps);
  EXPECT_EQ(f.ml_abstraction(), kAtS1);
  EXPECT_EQ(f.action(), kL);
  EXPECT_TRUE(belief_is_distribution(f, 2));
}

TEST(RuntimeFilter, WeighContextRejectsBadLikelihoodsWithoutChange) {
  DiscreteExample ex;
  FixedWorkspace<2> ws;
  AttentionFilter f(ex.view, FilterOptions{}, ws);
  f.start(kS2);
  f.step(kS3, 1.0, kR);  // (1, 0)
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double bad_value[] = {nan, 1.0};
  const double negative[] = {-0.5, 1.0};
  const double too_few[] = {1.0};
  EXPECT_EQ(f.weigh_context(bad_value, 2), StepStatus::kBadState);
  EXPECT_EQ(f.weigh_context(negative, 2), StepStatus::kBadState);
  EXPECT_EQ(f.weigh_context(too_few, 1), StepStatus::kBadState);
  EXPECT_EQ(f.weigh_context(nullptr, 2), StepStatus::kBadState);
  // Zero where the belief is not: nothing explains the sighting, the belief is kept.
  const double contradicts[] = {0.0, 1.0};
  EXPECT_EQ(f.weigh_context(contradicts, 2), StepStatus::kZeroLikelihood);
  EXPECT_NEAR(f.belief(kAtS3), 1.0, kEps);
  EXPECT_EQ(f.ml_abstraction(), kAtS3);
}

TEST(RuntimeFilter, WeighContextScalesTheRobustJointBelief) {
  DiscreteExample ex(true, 0.7);
  FixedWorkspace<2, 3> ws;
  FilterOptions options;
  options.mode = FilterMode::kJoint;
  AttentionFilter f(ex.view, options, ws);
  f.start(kS2);
  f.step(kS3, 1.0, kR);
  f.step(kS2, 0.0, kL);  // joint (kAtS3: .06, .28 | kAtS1: .07) / .41, as above
  const double sighting[] = {0.25, 1.0};
  EXPECT_EQ(f.weigh_context(sighting, 2), StepStatus::kOk);
  const double total = 0.25 * 0.34 + 1.0 * 0.07;
  EXPECT_NEAR(f.joint_belief(kAtS3, kS1), 0.25 * 0.06 / total, kEps);
  EXPECT_NEAR(f.joint_belief(kAtS3, kS2), 0.25 * 0.28 / total, kEps);
  EXPECT_NEAR(f.joint_belief(kAtS1, kS2), 0.07 / total, kEps);
  EXPECT_NEAR(f.belief(kAtS3) + f.belief(kAtS1), 1.0, kEps);
  EXPECT_NEAR(f.belief(kAtS1), 0.07 / total, kEps);
}

std::vector<double> hedged_workspace(const CatalogView& view, const HedgeOptions& options) {
  return std::vector<double>(HedgedFilter::workspace_size(view, options));
}

TEST(HedgedFilter, NeedsAnObservationModelAndSaneOptions) {
  DiscreteExample plain(false);
  HedgeOptions options;
  std::vector<double> ws = hedged_workspace(plain.view, options);
  EXPECT_EQ(HedgedFilter(plain.view, options, ws.data(), ws.size()).error(),
            oasis::rt::FilterError::kNoRobustSection);
  DiscreteExample ex(true, 0.7);
  ws = hedged_workspace(ex.view, options);
  EXPECT_EQ(HedgedFilter(ex.view, options, ws.data(), ws.size() - 1).error(),
            oasis::rt::FilterError::kWorkspaceTooSmall);
  options.share = 1.0;
  EXPECT_EQ(HedgedFilter(ex.view, options, ws.data(), ws.size()).error(),
            oasis::rt::FilterError::kBadOptions);
}

// The hedged filter breaks ties by the paper options' tie rule, through the same routine as
// AttentionFilter: at the uniform prior both abstractions tie; kKeep takes the lowest, kRandom
// draws among them, the same draws for the same seed, and both over several seeds.
TEST(HedgedFilter, TiesFollowTheTieRule) {
  DiscreteExample ex(true, 0.7);
  HedgeOptions options;
  std::vector<double> ws = hedged_workspace(ex.view, options);
  {
    HedgedFilter keep(ex.view, options, ws.data(), ws.size());
    ASSERT_TRUE(keep.ok());
    EXPECT_EQ(keep.ml_abstraction(), 0u);
  }
  options.paper.tie_rule = oasis::rt::TieRule::kRandom;
  bool picked[2] = {false, false};
  for (std::uint64_t seed = 0; seed < 32; ++seed) {
    options.paper.seed = seed;
    HedgedFilter first(ex.view, options, ws.data(), ws.size());
    ASSERT_TRUE(first.ok());
    const std::uint32_t choice = first.ml_abstraction();
    first.reset();
    EXPECT_EQ(first.ml_abstraction(), choice) << "the same seed draws the same";
    // AttentionFilter's own choice at the same prior, seed and rule: the one routine.
    FilterOptions paper = options.paper;
    FixedWorkspace<2, 3> alone_ws;
    AttentionFilter alone(ex.view, paper, alone_ws);
    EXPECT_EQ(alone.ml_abstraction(), choice) << seed;
    picked[choice] = true;
  }
  EXPECT_TRUE(picked[0] && picked[1]) << "the random rule never picked one of the tied";
}

// A wrong state with the true state's reward (the robust model's world, as in
// RobustModeSurvivesOneWrongStateObservation): Algorithm 1 explains r = 1 at s1 only by a switch
// it predicted with .2, the robust model by a wrong reading of s3 (p .15 against .7 for the
// other readings' sum), so the weight moves to the robust model, which is not fooled.
TEST(HedgedFilter, FollowsTheModelThatExplainsTheRewards) {
  DiscreteExample ex(true, 0.7);
  HedgeOptions options;
  std::vector<double> ws = hedged_workspace(ex.view, options);
  HedgedFilter f(ex.view, options, ws.data(), ws.size());
  ASSERT_TRUE(f.ok());
  f.start(kS3);
  for (int k = 0; k < 5; ++k)
    f.step(kS3, 1.0, kR);
  EXPECT_EQ(f.ml_abstraction(), kAtS3);
  const double before = f.robust_weight();
  EXPECT_EQ(f.step(kS1, 1.0, kR), StepStatus::kOk);
  EXPECT_EQ(f.paper_filter().ml_abstraction(), kAtS1) << "Algorithm 1 is fooled";
  EXPECT_GT(f.robust_weight(), before);
  EXPECT_GT(f.robust_weight(), 0.7);
  EXPECT_EQ(f.ml_abstraction(), kAtS3);
  EXPECT_EQ(f.action(), kR);
  double sum = 0.0;
  for (std::uint32_t i = 0; i < 2; ++i)
    sum += f.belief(i);
  EXPECT_NEAR(sum, 1.0, 1e-12);
}

// The reward follows the observed state (the paper's world): the robust model, which expects
// the true state's reward, is surprised more often than the paper's filter, and loses weight.
TEST(HedgedFilter, KeepsAlgorithmOneWhenItExplainsBetter) {
  DiscreteExample ex(true, 0.7);
  HedgeOptions options;
  std::vector<double> ws = hedged_workspace(ex.view, options);
  HedgedFilter f(ex.view, options, ws.data(), ws.size());
  f.start(kS3);
  for (int k = 0; k < 5; ++k)
    f.step(kS3, 1.0, kR);
  // Seen at s1 and paid as object_at_s1's s1: exactly what Algorithm 1 explains with a switch.
  for (int k = 0; k < 5; ++k)
    f.step(kS1, 1.0, kL);
  EXPECT_LT(f.robust_weight(), 0.5);
  EXPECT_EQ(f.ml_abstraction(), f.paper_filter().ml_abstraction());
  EXPECT_EQ(f.ml_abstraction(), kAtS1);
  EXPECT_EQ(f.action(), kL);
}

}  // namespace
