// The model checker on small models whose values are known in closed form: Knuth and Yao's
// die, MDPs with end components (where Pmax needs the collapse and its scheduler must leave),
// Rmin with a zero-reward end component, infinite rewards, the step-bounded operators, and the
// exact mode's limits. Each property in both modes: exactly in kExact, inside an interval of
// width <= precision in kSound.

#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "modelcheck/engine.hpp"
#include "modelcheck_models.hpp"

namespace oasis {
namespace {

using modelcheck::ExactLimitExceeded;
using modelcheck::Mode;
using modelcheck::Optimum;
using modelcheck::Options;
using modelcheck::Result;
using modelcheck::Scheduler;
using modelcheck::StateSet;
using test::CheckModel;
using test::hand_model;

Options exact_options(bool scheduler = false) {
  Options options;
  options.mode = Mode::kExact;
  options.want_scheduler = scheduler;
  return options;
}

Options sound_options(bool scheduler = false) {
  Options options;
  options.mode = Mode::kSound;
  options.precision = 1e-9;
  options.want_scheduler = scheduler;
  return options;
}

StateSet only(std::uint32_t n, std::vector<std::uint32_t> members) {
  StateSet set(n, false);
  for (const std::uint32_t s : members)
    set[s] = true;
  return set;
}

void expect_inside(const Result& result, std::uint32_t s, const Rational& exact, double precision) {
  const modelcheck::Value& value = result.values[s];
  EXPECT_FALSE(value.infinite) << "state " << s;
  EXPECT_LE(Rational(value.lower), exact) << "state " << s;
  EXPECT_GE(Rational(value.upper), exact) << "state " << s;
  EXPECT_LE(value.upper - value.lower, precision) << "state " << s;
}

// Knuth and Yao's die: a fair coin simulates a fair die. States 0..6 toss, 7..12 are the
// faces 1..6 and have no enabled action (PRISM's self-loop).
CheckModel knuth_yao_die() {
  const Rational h(1, 2);
  return hand_model(13, 1,
                    {{0, 0, 1, h},
                     {0, 0, 2, h},
                     {1, 0, 3, h},
                     {1, 0, 4, h},
                     {2, 0, 5, h},
                     {2, 0, 6, h},
                     {3, 0, 1, h},
                     {3, 0, 7, h},
                     {4, 0, 8, h},
                     {4, 0, 9, h},
                     {5, 0, 10, h},
                     {5, 0, 11, h},
                     {6, 0, 2, h},
                     {6, 0, 12, h}},
                    {1, 1, 1, 1, 1, 1, 1, 0, 0, 0, 0, 0, 0});
}

TEST(ModelcheckKnownValues, KnuthYaoDieGivesEachFaceOneSixthExactly) {
  const CheckModel die = knuth_yao_die();
  const StateSet all(13, true);
  for (std::uint32_t face = 7; face <= 12; ++face) {
    const Result exact =
        modelcheck::until(die.problem(Optimum::kNone), all, only(13, {face}), exact_options());
    EXPECT_EQ(exact.values[0].exact, Rational(1, 6)) << "face " << face - 6;
    EXPECT_NE(exact.method.find("exact"), std::string::npos);
    const Result sound =
        modelcheck::until(die.problem(Optimum::kNone), all, only(13, {face}), sound_options());
    expect_inside(sound, 0, Rational(1, 6), 1e-9);
    EXPECT_NE(sound.method.find("interval iteration"), std::string::npos) << sound.method;
  }
}

TEST(ModelcheckKnownValues, KnuthYaoDieTakesElevenThirdsTossesOnAverage) {
  const CheckModel die = knuth_yao_die();
  const StateSet faces = only(13, {7, 8, 9, 10, 11, 12});
  const Result exact = modelcheck::reachability_reward(die.problem(Optimum::kNone), die.rewards,
                                                       faces, exact_options());
  EXPECT_EQ(exact.values[0].exact, Rational(11, 3));
  EXPECT_EQ(exact.values[7].exact, 0);
  const Result sound = modelcheck::reachability_reward(die.problem(Optimum::kNone), die.rewards,
                                                       faces, sound_options());
  expect_inside(sound, 0, Rational(11, 3), 1e-9);
}

// 0 and 3 form an end component (a: 0 -> 3 -> 0) with two exits: 0 by b wins with 1/2, 3 by b
// with 1/3. 1 is the goal and 2 the failure; neither has an action.
CheckModel end_component_mdp() {
  return hand_model(4, 2,
                    {{0, 0, 3, 1},
                     {3, 0, 0, 1},
                     {0, 1, 1, Rational(1, 2)},
                     {0, 1, 2, Rational(1, 2)},
                     {3, 1, 1, Rational(1, 3)},
                     {3, 1, 2, Rational(2, 3)}});
}

TEST(ModelcheckKnownValues, PmaxThroughAnEndComponentTakesItsBestExit) {
  const CheckModel m = end_component_mdp();
  const StateSet all(4, true);
  const StateSet goal = only(4, {1});
  const Result max = modelcheck::until(m.problem(Optimum::kMax), all, goal, exact_options(true));
  EXPECT_EQ(max.values[0].exact, Rational(1, 2));
  EXPECT_EQ(max.values[3].exact, Rational(1, 2));
  // Staying in the end component keeps the value 1/2 but never reaches: 3 must head for 0.
  ASSERT_TRUE(max.scheduler.has_value());
  EXPECT_EQ(max.scheduler->action[0], 1U);
  EXPECT_EQ(max.scheduler->action[3], 0U);
  const Result min = modelcheck::until(m.problem(Optimum::kMin), all, goal, exact_options(true));
  EXPECT_EQ(min.values[0].exact, 0);
  EXPECT_EQ(min.values[3].exact, 0);
  // Pmin = 0 needs the cycle, not an exit.
  EXPECT_EQ(min.scheduler->action[0], 0U);
  EXPECT_EQ(min.scheduler->action[3], 0U);
  const Result sound = modelcheck::until(m.problem(Optimum::kMax), all, goal, sound_options());
  expect_inside(sound, 3, Rational(1, 2), 1e-9);
}

TEST(ModelcheckKnownValues, PmaxOneChoosesTheChoiceThatReaches) {
  // 0: a reaches 1 or retries; b stays forever. Both keep Pmax = 1 at 0, only a reaches.
  const CheckModel m =
      hand_model(2, 2, {{0, 0, 0, Rational(1, 2)}, {0, 0, 1, Rational(1, 2)}, {0, 1, 0, 1}});
  const Result max = modelcheck::until(m.problem(Optimum::kMax), StateSet(2, true), only(2, {1}),
                                       exact_options(true));
  EXPECT_EQ(max.values[0].exact, 1);
  EXPECT_EQ(max.scheduler->action[0], 0U);
  const Result min = modelcheck::until(m.problem(Optimum::kMin), StateSet(2, true), only(2, {1}),
                                       exact_options(true));
  EXPECT_EQ(min.values[0].exact, 0);
  EXPECT_EQ(min.scheduler->action[0], 1U);
}

TEST(ModelcheckKnownValues, UntilStopsAtStatesOutsidePhi) {
  // 0 -> 1 -> 2 (goal), all surely; phi excludes 1, so only the goal itself satisfies it.
  const CheckModel m = hand_model(3, 1, {{0, 0, 1, 1}, {1, 0, 2, 1}});
  const Result r =
      modelcheck::until(m.problem(Optimum::kNone), only(3, {0}), only(3, {2}), exact_options());
  EXPECT_EQ(r.values[0].exact, 0);
  EXPECT_EQ(r.values[1].exact, 0);
  EXPECT_EQ(r.values[2].exact, 1);
}

TEST(ModelcheckKnownValues, RminLeavesAZeroRewardEndComponentByItsCheapestExit) {
  // 0 and 1 cycle at no cost (a); b reaches the target 2, at 5 from 0 and at 2 from 1. Rmin is
  // 2 in both, not the 0 of staying forever (which never reaches and so costs infinity).
  const CheckModel m = hand_model(3, 2, {{0, 0, 1, 1}, {1, 0, 0, 1}, {0, 1, 2, 1}, {1, 1, 2, 1}},
                                  {0, 0, 0}, {0, 5, 0, 2, 0, 0});
  const StateSet target = only(3, {2});
  for (const Options& options : {exact_options(true), sound_options(true)}) {
    const Result min =
        modelcheck::reachability_reward(m.problem(Optimum::kMin), m.rewards, target, options);
    expect_inside(min, 0, 2, 1e-9);
    expect_inside(min, 1, 2, 1e-9);
    EXPECT_EQ(min.scheduler->action[0], 0U);
    EXPECT_EQ(min.scheduler->action[1], 1U);
    // Rmax: the cycle misses the target for ever.
    const Result max =
        modelcheck::reachability_reward(m.problem(Optimum::kMax), m.rewards, target, options);
    EXPECT_TRUE(max.values[0].infinite);
    EXPECT_TRUE(max.values[1].infinite);
    EXPECT_EQ(max.scheduler->action[0], 0U);
    EXPECT_EQ(max.scheduler->action[1], 0U);
  }
}

TEST(ModelcheckKnownValues, RewardIsInfiniteWhereTheTargetMayBeMissed) {
  // 0 reaches the target 1 or the trap 2 with 1/2 each; 3 reaches the target surely.
  const CheckModel m = hand_model(
      4, 1, {{0, 0, 1, Rational(1, 2)}, {0, 0, 2, Rational(1, 2)}, {3, 0, 1, 1}}, {1, 0, 1, 7});
  const StateSet target = only(4, {1});
  for (const Options& options : {exact_options(), sound_options()}) {
    const Result r =
        modelcheck::reachability_reward(m.problem(Optimum::kNone), m.rewards, target, options);
    EXPECT_TRUE(r.values[0].infinite);
    EXPECT_FALSE(r.values[1].infinite);
    EXPECT_TRUE(r.values[2].infinite);
    expect_inside(r, 3, 7, 1e-9);
  }
}

TEST(ModelcheckKnownValues, NegativeRewardsAreRefused) {
  const CheckModel m = hand_model(2, 1, {{0, 0, 1, 1}}, {-1, 0});
  EXPECT_THROW(modelcheck::reachability_reward(m.problem(Optimum::kNone), m.rewards, only(2, {1}),
                                               exact_options()),
               std::invalid_argument);
}

// 0 flips a coin each step: heads (1/2) to the goal 1, tails back to 0; it earns 1 per step.
CheckModel geometric_chain() {
  return hand_model(2, 1, {{0, 0, 0, Rational(1, 2)}, {0, 0, 1, Rational(1, 2)}}, {1, 0});
}

TEST(ModelcheckKnownValues, BoundedOperatorsOnAGeometricChain) {
  const CheckModel m = geometric_chain();
  const StateSet all(2, true);
  const StateSet goal = only(2, {1});
  for (std::uint32_t k = 0; k <= 12; ++k) {
    const Rational power(1, mpz_class(1) << k);
    const Result until =
        modelcheck::bounded_until(m.problem(Optimum::kNone), all, goal, k, exact_options());
    EXPECT_EQ(until.values[0].exact, 1 - power) << k;
    const Result cumulative =
        modelcheck::cumulative_reward(m.problem(Optimum::kNone), m.rewards, k, exact_options());
    EXPECT_EQ(cumulative.values[0].exact, 2 - 2 * power) << k;
    const Result instantaneous =
        modelcheck::instantaneous_reward(m.problem(Optimum::kNone), m.rewards, k, exact_options());
    EXPECT_EQ(instantaneous.values[0].exact, power) << k;
    // Sound: the same up to rounding only.
    const Result sound =
        modelcheck::cumulative_reward(m.problem(Optimum::kNone), m.rewards, k, sound_options());
    expect_inside(sound, 0, 2 - 2 * power, 1e-12);
  }
  const Result next = modelcheck::next(m.problem(Optimum::kNone), goal, exact_options());
  EXPECT_EQ(next.values[0].exact, Rational(1, 2));
  EXPECT_EQ(next.values[1].exact, 1);  // the goal's self-loop
}

TEST(ModelcheckKnownValues, BoundedPmaxSchedulerDependsOnTheStepsLeft) {
  // 0: a reaches the goal 1 with 1/2 and retries; b goes to 2, which reaches the goal surely.
  // With one step left a is best (1/2 against 0); with two, b (1 against 3/4).
  const CheckModel m = hand_model(
      3, 2, {{0, 0, 1, Rational(1, 2)}, {0, 0, 0, Rational(1, 2)}, {0, 1, 2, 1}, {2, 0, 1, 1}});
  const StateSet all(3, true);
  const StateSet goal = only(3, {1});
  const Result one =
      modelcheck::bounded_until(m.problem(Optimum::kMax), all, goal, 1, exact_options(true));
  EXPECT_EQ(one.values[0].exact, Rational(1, 2));
  ASSERT_EQ(one.scheduler->by_step.size(), 1U);
  EXPECT_EQ(one.scheduler->by_step[0][0], 0U);
  for (const Options& options : {exact_options(true), sound_options(true)}) {
    const Result two = modelcheck::bounded_until(m.problem(Optimum::kMax), all, goal, 2, options);
    expect_inside(two, 0, 1, 1e-12);
    ASSERT_EQ(two.scheduler->by_step.size(), 2U);
    EXPECT_EQ(two.scheduler->by_step[0][0], 1U);
    EXPECT_EQ(two.scheduler->by_step[1][0], 0U);
    EXPECT_TRUE(two.scheduler->action.empty());
  }
  const Result min =
      modelcheck::bounded_until(m.problem(Optimum::kMin), all, goal, 2, exact_options(true));
  // Pmin: a first (then 1/2 * 0 after b), where b first would reach surely.
  EXPECT_EQ(min.values[0].exact, Rational(1, 2));
  EXPECT_EQ(min.scheduler->by_step[0][0], 0U);
  EXPECT_EQ(min.scheduler->by_step[1][0], 1U);
}

TEST(ModelcheckKnownValues, ExactModeRefusesPastItsLimits) {
  const CheckModel die = knuth_yao_die();
  Options options = exact_options();
  options.max_exact_states = 2;  // face 1 leaves 3 states of unknown value
  try {
    modelcheck::until(die.problem(Optimum::kNone), StateSet(13, true), only(13, {7}), options);
    FAIL() << "no ExactLimitExceeded";
  } catch (const ExactLimitExceeded& e) {
    EXPECT_NE(std::string(e.what()).find("--mode sound"), std::string::npos) << e.what();
  }
  // 1 - 2^-100 needs 100 bits.
  options = exact_options();
  options.max_number_bits = 64;
  const CheckModel m = geometric_chain();
  EXPECT_THROW(modelcheck::bounded_until(m.problem(Optimum::kNone), StateSet(2, true), only(2, {1}),
                                         100, options),
               ExactLimitExceeded);
}

TEST(ModelcheckKnownValues, GamblersRuinOnALongChainIsExact) {
  // 0 and N absorb; from 0 < i < N the walk moves up or down with 1/2: P(F N) from i is i/N.
  constexpr std::uint32_t kN = 20000;
  std::vector<test::HandEdge> edges;
  for (std::uint32_t i = 1; i < kN; ++i) {
    edges.push_back({i, 0, i - 1, Rational(1, 2)});
    edges.push_back({i, 0, i + 1, Rational(1, 2)});
  }
  const CheckModel m = hand_model(kN + 1, 1, edges);
  const Result r = modelcheck::until(m.problem(Optimum::kNone), StateSet(kN + 1, true),
                                     only(kN + 1, {kN}), exact_options());
  for (const std::uint32_t i : {0U, 1U, 7U, kN / 2, kN - 1, kN}) {
    Rational expected(i, kN);
    expected.canonicalize();
    EXPECT_EQ(r.values[i].exact, expected) << i;
  }
}

}  // namespace
}  // namespace oasis
