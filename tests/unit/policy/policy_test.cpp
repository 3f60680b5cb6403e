// Policies: value iteration and backward induction on small models whose values are known in
// closed form, the paper's discrete example, and the property the quotient exists for:
// solving the quotient gives the full model's optimal values, and its policy, lifted back to
// the states, is optimal on the full model (random models, tests/support/random_mdp.hpp).

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "../../support/random_mdp.hpp"
#include "../../support/spec_models.hpp"
#include "bisim/quotient.hpp"
#include "bisim/refinement.hpp"
#include "policy/policy_evaluation.hpp"
#include "policy/value_iteration.hpp"

namespace oasis {
namespace {

using model::ActionIndex;
using model::ExplicitModel;
using model::Partition;
using model::StateIndex;
using policy::kNoAction;
using policy::PolicyOptions;

// Sanitizers make everything ~10x slower.
#if defined(__SANITIZE_ADDRESS__)
constexpr std::uint64_t kModels = 300;
#else
constexpr std::uint64_t kModels = 1500;
#endif
constexpr double kClose = 1e-6;

struct Edge {
  StateIndex from;
  ActionIndex action;
  StateIndex to;
  Rational probability;
};

// One context; `state_rewards[s]` is R(s), and choice rewards are left out.
ExplicitModel hand_model(std::uint32_t num_states, std::uint32_t num_actions,
                         const std::vector<Edge>& edges, const std::vector<Rational>& state_rewards,
                         std::optional<Rational> discount = Rational(9, 10)) {
  ExplicitModel model;
  model.name = "hand";
  model.states.size = num_states;
  for (StateIndex s = 0; s < num_states; ++s)
    model.states.names.push_back("s" + std::to_string(s));
  model.states.initial = {0};
  for (ActionIndex a = 0; a < num_actions; ++a)
    model.actions.push_back("a" + std::to_string(a));
  model::TransitionBuilder builder(num_states, num_actions);
  for (const Edge& edge : edges)
    builder.add(edge.from, edge.action, edge.to, model.values.intern(edge.probability));
  model::RewardTable rewards;
  for (const Rational& r : state_rewards)
    rewards.state.push_back(model.values.intern(r));
  model.contexts.push_back(
      {"c", std::make_shared<const model::TransitionMatrix>(builder.finish(model.values)),
       std::move(rewards)});
  model.objective.discount = std::move(discount);
  return model;
}

TEST(Policy, TwoStateChainHasItsClosedFormValue) {
  // s0 earns 1 and stays with probability 1/2; s1 earns nothing forever.
  // V(s0) = 1 + 0.9 (V(s0) / 2), so V(s0) = 1 / 0.55 = 20/11.
  const ExplicitModel model =
      hand_model(2, 1, {{0, 0, 0, Rational(1, 2)}, {0, 0, 1, Rational(1, 2)}, {1, 0, 1, 1}},
                 {Rational(1), Rational(0)});
  const policy::Policy result = policy::solve(model, 0);
  EXPECT_TRUE(result.converged);
  EXPECT_FALSE(result.objective.default_discount);
  EXPECT_DOUBLE_EQ(result.objective.discount, 0.9);
  EXPECT_NEAR(result.value[0], 20.0 / 11.0, 1e-9);
  EXPECT_NEAR(result.value[1], 0.0, 1e-9);
  EXPECT_EQ(result.action, (std::vector<ActionIndex>{0, 0}));
  const std::vector<double> evaluated = policy::evaluate(model, 0, result.action);
  EXPECT_NEAR(evaluated[0], 20.0 / 11.0, 1e-9);

  // Three steps, undiscounted: 1, 1 + 1/2, 1 + 1/2 * 3/2.
  PolicyOptions three;
  three.horizon = 3;
  const policy::Policy finite = policy::solve(model, 0, three);
  EXPECT_TRUE(finite.converged);
  EXPECT_EQ(finite.iterations, 3u);
  EXPECT_DOUBLE_EQ(finite.objective.discount, 1.0);
  EXPECT_NEAR(finite.value[0], 1.75, 1e-12);
  EXPECT_NEAR(policy::evaluate(model, 0, finite.action, three)[0], 1.75, 1e-12);
}

TEST(Policy, BetterActionIsChosenAndTiesGoToTheSmallestIndex) {
  // s0: a0 and a2 both lead to s1 (earning 1 forever), a1 to s2 (earning 0 forever).
  const ExplicitModel model = hand_model(
      3, 3, {{0, 0, 1, 1}, {0, 1, 2, 1}, {0, 2, 1, 1}, {1, 0, 1, 1}, {2, 1, 2, 1}, {2, 2, 1, 1}},
      {Rational(0), Rational(1), Rational(0)});
  const policy::Policy result = policy::solve(model, 0);
  // s2: a1 stays (0), a2 escapes to s1 (value 0.9 * 10): a2. s1 has only a0.
  EXPECT_EQ(result.action, (std::vector<ActionIndex>{0, 0, 2}));
  EXPECT_NEAR(result.value[0], 9.0, 1e-9);
}

TEST(Policy, DeadEndsCollectTheirStateReward) {
  // s1 has no enabled action and reward 2: 2 / (1 - 0.9) = 20; s0 reaches it in one step.
  const ExplicitModel model = hand_model(2, 1, {{0, 0, 1, 1}}, {Rational(0), Rational(2)});
  const policy::Policy result = policy::solve(model, 0);
  EXPECT_EQ(result.action, (std::vector<ActionIndex>{0, kNoAction}));
  EXPECT_NEAR(result.value[1], 20.0, 1e-12);
  EXPECT_NEAR(result.value[0], 18.0, 1e-9);
  PolicyOptions three;
  three.horizon = 3;
  const policy::Policy finite = policy::solve(model, 0, three);
  EXPECT_NEAR(finite.value[1], 6.0, 1e-12);
  EXPECT_NEAR(finite.value[0], 4.0, 1e-12);
  EXPECT_NEAR(policy::evaluate(model, 0, finite.action, three)[1], 6.0, 1e-12);
}

TEST(Policy, ObjectiveComesFromOptionsThenModelThenDefault) {
  ExplicitModel model = hand_model(1, 1, {{0, 0, 0, 1}}, {Rational(1)}, std::nullopt);
  const policy::Policy defaulted = policy::solve(model, 0);
  EXPECT_TRUE(defaulted.objective.default_discount);
  EXPECT_DOUBLE_EQ(defaulted.objective.discount, policy::kDefaultDiscount);
  EXPECT_NEAR(defaulted.value[0], 20.0, 1e-8);

  model.objective.horizon = 4;
  EXPECT_NEAR(policy::solve(model, 0).value[0], 4.0, 1e-12);
  PolicyOptions half;
  half.discount = 0.5;  // the options replace the model's objective entirely
  EXPECT_NEAR(policy::solve(model, 0, half).value[0], 2.0, 1e-9);

  PolicyOptions undiscounted;
  undiscounted.discount = 1.0;
  EXPECT_THROW(policy::solve(model, 0, undiscounted), std::invalid_argument);
  PolicyOptions zero_horizon;
  zero_horizon.horizon = 0;
  EXPECT_THROW(policy::solve(model, 0, zero_horizon), std::invalid_argument);
  EXPECT_THROW(policy::evaluate(model, 0, {0, 0}), std::invalid_argument);
}

TEST(Policy, IterationLimitIsReportedAsNotConverged) {
  const ExplicitModel model = hand_model(1, 1, {{0, 0, 0, 1}}, {Rational(1)});
  PolicyOptions options;
  options.max_iterations = 3;
  const policy::Policy result = policy::solve(model, 0, options);
  EXPECT_FALSE(result.converged);
  EXPECT_EQ(result.iterations, 3u);
  EXPECT_NEAR(result.value[0], 1 + 0.9 + 0.81, 1e-12);
  EXPECT_NEAR(result.residual, 0.81, 1e-12);
}

StateIndex state_named(const ExplicitModel& model, const std::string& name) {
  for (StateIndex s = 0; s < model.num_states(); ++s) {
    if (model.states.name(s) == name) return s;
  }
  ADD_FAILURE() << "no state " << name;
  return 0;
}

std::size_t context_named(const ExplicitModel& model, const std::string& name) {
  for (std::size_t c = 0; c < model.contexts.size(); ++c) {
    if (model.contexts[c].name == name) return c;
  }
  ADD_FAILURE() << "no context " << name;
  return 0;
}

ActionIndex action_named(const ExplicitModel& model, const std::string& name) {
  for (ActionIndex a = 0; a < model.num_actions(); ++a) {
    if (model.actions[a] == name) return a;
  }
  ADD_FAILURE() << "no action " << name;
  return 0;
}

// By hand, discount 0.9, context object_at_s3 (R(s3) = 1): staying at s3 with R earns 10.
// In the block {s1, s2}, R reaches s3 with probability 1/2 and L never does, so
// V(b) = 0.9 (V(b)/2 + 10/2), V(b) = 4.5 / 0.55 = 90/11. At s3, L would give
// 1 + 0.9 * 90/11 < 10: R is strictly better there, so no tie arises. R everywhere;
// object_at_s1 is the mirror image: L everywhere.
TEST(Policy, DiscreteTrackingExampleByHand) {
  const ExplicitModel model =
      test::explore_spec_file(std::string(OASIS_SOURCE_DIR) + "/specs/discrete_tracking.oasis");
  ASSERT_EQ(model.num_states(), 3u);
  const StateIndex s1 = state_named(model, "s1");
  const StateIndex s2 = state_named(model, "s2");
  const StateIndex s3 = state_named(model, "s3");
  const ActionIndex left = action_named(model, "L");
  const ActionIndex right = action_named(model, "R");
  struct Case {
    std::string context;
    ActionIndex action;
    StateIndex goal;
  };
  for (const Case& expected : {Case{"object_at_s3", right, s3}, Case{"object_at_s1", left, s1}}) {
    SCOPED_TRACE(expected.context);
    const std::size_t c = context_named(model, expected.context);
    const policy::Policy full = policy::solve(model, c);
    EXPECT_DOUBLE_EQ(full.objective.discount, 0.9);
    EXPECT_EQ(full.action, std::vector<ActionIndex>(3, expected.action));
    for (StateIndex s : {s1, s2, s3}) {
      EXPECT_NEAR(full.value[s], s == expected.goal ? 10.0 : 90.0 / 11.0, 1e-9);
    }
    const Partition partition = bisim::coarsest_bisimulation(model, c);
    ASSERT_EQ(partition.num_blocks, 2u);
    const policy::Policy abstract = policy::solve(bisim::build_quotient(model, c, partition), 0);
    EXPECT_EQ(abstract.action, std::vector<ActionIndex>(2, expected.action));
    EXPECT_EQ(policy::lift(abstract.action, partition), full.action);
  }
}

std::string where(std::uint64_t seed, std::size_t context) {
  return "seed " + std::to_string(seed) + ", context " + std::to_string(context);
}

// R(s, a) + γ Σ P(s'|s,a) V(s') from the exact model, independently of the policy layer.
double q_value(const ExplicitModel& model, std::size_t context, const std::vector<double>& value,
               StateIndex s, ActionIndex a, double discount) {
  const model::TransitionMatrix& matrix = *model.contexts[context].transitions;
  double expected = 0;
  for (model::EdgeIndex e = matrix.edges_begin(s, a); e < matrix.edges_end(s, a); ++e)
    expected += to_double(model.values[matrix.edge_probability[e]]) * value[matrix.edge_target[e]];
  return to_double(model.reward(context, s, a)) + discount * expected;
}

// The largest |V_full(s) - V_quotient(block(s))|.
double quotient_value_gap(const ExplicitModel& model, std::size_t context,
                          const Partition& partition, const PolicyOptions& options) {
  const policy::Policy full = policy::solve(model, context, options);
  const policy::Policy abstract =
      policy::solve(bisim::build_quotient(model, context, partition), 0, options);
  double gap = 0;
  for (StateIndex s = 0; s < model.num_states(); ++s)
    gap = std::max(gap, std::abs(full.value[s] - abstract.value[partition.block_of[s]]));
  return gap;
}

// The discounts vary with the seed so that slow (0.95) and fast (0.5) convergence both occur.
PolicyOptions discounted_options(std::uint64_t seed) {
  constexpr std::array<double, 3> kDiscounts{0.5, 0.9, 0.95};
  PolicyOptions options;
  options.discount = kDiscounts[seed % kDiscounts.size()];
  return options;
}

TEST(PolicyProperty, QuotientPreservesOptimalDiscountedValuesAndPolicies) {
  std::uint64_t contexts = 0;
  std::uint64_t merged = 0;  // contexts whose quotient is smaller than the model
  for (std::uint64_t seed = 1; seed <= kModels; ++seed) {
    const ExplicitModel model = test::random_mdp(seed);
    const PolicyOptions options = discounted_options(seed);
    for (std::size_t c = 0; c < model.contexts.size(); ++c, ++contexts) {
      SCOPED_TRACE(where(seed, c));
      const Partition partition = bisim::coarsest_bisimulation(model, c);
      const ExplicitModel quotient = bisim::build_quotient(model, c, partition);
      const policy::Policy full = policy::solve(model, c, options);
      const policy::Policy abstract = policy::solve(quotient, 0, options);
      ASSERT_TRUE(full.converged && abstract.converged);
      if (partition.num_blocks < model.num_states()) ++merged;
      // (a) V_full(s) = V_quotient(block(s)).
      for (StateIndex s = 0; s < model.num_states(); ++s) {
        ASSERT_NEAR(full.value[s], abstract.value[partition.block_of[s]], kClose) << "state " << s;
      }
      // (b) The lifted quotient policy is optimal on the full model, and it has there the
      // values the quotient policy has on the quotient.
      const std::vector<ActionIndex> lifted = policy::lift(abstract.action, partition);
      const std::vector<double> on_full = policy::evaluate(model, c, lifted, options);
      const std::vector<double> on_quotient =
          policy::evaluate(quotient, 0, abstract.action, options);
      for (StateIndex s = 0; s < model.num_states(); ++s) {
        ASSERT_NEAR(on_full[s], full.value[s], kClose) << "state " << s;
        ASSERT_NEAR(on_full[s], on_quotient[partition.block_of[s]], kClose) << "state " << s;
      }
    }
  }
  EXPECT_GE(contexts, kModels);
  // The property says little about quotients that merge nothing.
  EXPECT_GE(merged, contexts / 2) << merged << " of " << contexts << " contexts merge states";
}

// With a horizon the stored policy is the first step of the optimal plan, so optimality of the
// lifted policy means: its first action reaches V*_H given V*_{H-1} afterwards.
TEST(PolicyProperty, QuotientPreservesOptimalFiniteHorizonValuesAndPolicies) {
  constexpr std::uint32_t kHorizon = 5;
  for (std::uint64_t seed = 1; seed <= kModels; ++seed) {
    const ExplicitModel model = test::random_mdp(seed);
    PolicyOptions options;
    options.horizon = kHorizon;
    if (seed % 2 == 0) options.discount = 0.9;
    PolicyOptions shorter = options;
    shorter.horizon = kHorizon - 1;
    const double discount = options.discount.value_or(1.0);
    for (std::size_t c = 0; c < model.contexts.size(); ++c) {
      SCOPED_TRACE(where(seed, c));
      const Partition partition = bisim::coarsest_bisimulation(model, c);
      const ExplicitModel quotient = bisim::build_quotient(model, c, partition);
      const policy::Policy full = policy::solve(model, c, options);
      const policy::Policy abstract = policy::solve(quotient, 0, options);
      const std::vector<double> rest = policy::solve(model, c, shorter).value;
      const std::vector<ActionIndex> lifted = policy::lift(abstract.action, partition);
      const std::vector<double> on_full = policy::evaluate(model, c, lifted, options);
      const std::vector<double> on_quotient =
          policy::evaluate(quotient, 0, abstract.action, options);
      for (StateIndex s = 0; s < model.num_states(); ++s) {
        ASSERT_NEAR(full.value[s], abstract.value[partition.block_of[s]], kClose) << "state " << s;
        ASSERT_EQ(lifted[s] == kNoAction, full.action[s] == kNoAction) << "state " << s;
        if (lifted[s] != kNoAction) {
          ASSERT_NEAR(q_value(model, c, rest, s, lifted[s], discount), full.value[s], kClose)
              << "state " << s;
        }
        ASSERT_NEAR(on_full[s], on_quotient[partition.block_of[s]], kClose) << "state " << s;
      }
    }
  }
}

// The property tests above must be able to fail: with two blocks of different optimal value
// merged, the "quotient" no longer has the full model's values for some models.
TEST(PolicyProperty, WrongPartitionBreaksValueEquality) {
  std::uint64_t broken = 0;
  std::uint64_t tried = 0;
  for (std::uint64_t seed = 1; seed <= 100; ++seed) {
    const ExplicitModel model = test::random_mdp(seed);
    const PolicyOptions options = discounted_options(seed);
    const Partition partition = bisim::coarsest_bisimulation(model, 0);
    if (partition.num_blocks < 2) continue;
    const policy::Policy full = policy::solve(model, 0, options);
    // Merge the block of the state with the largest value into that of the smallest.
    StateIndex high = 0;
    StateIndex low = 0;
    for (StateIndex s = 0; s < model.num_states(); ++s) {
      if (full.value[s] > full.value[high]) high = s;
      if (full.value[s] < full.value[low]) low = s;
    }
    if (full.value[high] - full.value[low] < 1e-3) continue;
    std::vector<std::uint32_t> labels(partition.block_of.begin(), partition.block_of.end());
    for (std::uint32_t& label : labels) {
      if (label == partition.block_of[high]) label = partition.block_of[low];
    }
    ++tried;
    if (quotient_value_gap(model, 0, model::canonical_partition(labels), options) > kClose)
      ++broken;
    EXPECT_LE(quotient_value_gap(model, 0, partition, options), kClose) << "seed " << seed;
  }
  EXPECT_GT(tried, 10u);
  EXPECT_EQ(broken, tried) << "a merge of states with different values went unnoticed";
}

}  // namespace
}  // namespace oasis
