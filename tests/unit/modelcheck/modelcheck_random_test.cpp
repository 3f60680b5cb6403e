// The model checker on seeded random MDPs (tests/support/random_mdp.hpp) against references
// that owe nothing to it (modelcheck_models.hpp): on tiny models the exact optimum equals the
// best of all memoryless deterministic schedulers, each solved by dense elimination; on larger
// ones the sound interval contains the exact value and is no wider than the precision; and the
// scheduler the engine returns, applied to the model, gives the value it claims (exactly the
// same rational in exact mode).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "modelcheck/engine.hpp"
#include "modelcheck_models.hpp"

namespace oasis {
namespace {

using model::ActionIndex;
using modelcheck::Mode;
using modelcheck::Optimum;
using modelcheck::Options;
using modelcheck::Result;
using modelcheck::Scheduler;
using modelcheck::StateSet;
using test::CheckModel;
using test::TestRandom;

#if defined(__SANITIZE_ADDRESS__)
constexpr std::uint64_t kModels = 60;
#else
constexpr std::uint64_t kModels = 400;
#endif
constexpr double kPrecision = 1e-6;

Options options_for(Mode mode, bool scheduler) {
  Options options;
  options.mode = mode;
  options.precision = kPrecision;
  options.want_scheduler = scheduler;
  return options;
}

std::string where(std::uint64_t seed, Optimum optimum, std::uint32_t s) {
  return "seed " + std::to_string(seed) + ", optimum " + std::to_string(static_cast<int>(optimum)) +
         ", state " + std::to_string(s);
}

// A value of the engine as the reference writes it: nullopt for infinity.
std::optional<Rational> as_reference(const modelcheck::Value& value) {
  if (value.infinite) return std::nullopt;
  return value.exact;
}

// What a sound value must satisfy beside the exact one.
void expect_sound(const modelcheck::Value& sound, const modelcheck::Value& exact,
                  const std::string& context) {
  ASSERT_EQ(sound.infinite, exact.infinite) << context;
  if (exact.infinite) return;
  EXPECT_LE(Rational(sound.lower), exact.exact) << context;
  EXPECT_GE(Rational(sound.upper), exact.exact) << context;
  EXPECT_LE(sound.upper - sound.lower, kPrecision) << context;
}

TEST(ModelcheckRandom, ExactOptimaAreTheBestMemorylessSchedulers) {
  std::uint64_t compared = 0;
  for (std::uint64_t seed = 1; seed <= kModels; ++seed) {
    const CheckModel m = test::random_check_model(seed, 6, 3);
    const std::uint32_t n = m.matrix.num_states;
    TestRandom random(seed * 7919);
    const StateSet phi = test::random_set(random, n, 80);
    const StateSet psi = test::random_set(random, n, 25);
    const StateSet target = test::random_set(random, n, 30);
    for (const Optimum optimum : {Optimum::kMin, Optimum::kMax}) {
      const Result until =
          modelcheck::until(m.problem(optimum), phi, psi, options_for(Mode::kExact, false));
      const std::vector<Rational> best = test::brute_force_until(m, optimum, phi, psi);
      const Result reward = modelcheck::reachability_reward(m.problem(optimum), m.rewards, target,
                                                            options_for(Mode::kExact, false));
      const std::vector<std::optional<Rational>> best_reward =
          test::brute_force_reward(m, optimum, target);
      for (std::uint32_t s = 0; s < n; ++s) {
        EXPECT_EQ(until.values[s].exact, best[s]) << where(seed, optimum, s);
        EXPECT_EQ(as_reference(reward.values[s]), best_reward[s]) << where(seed, optimum, s);
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, kModels * 4);
}

TEST(ModelcheckRandom, AMarkovChainIsTheFirstActionOfEachState) {
  for (std::uint64_t seed = 1; seed <= kModels; ++seed) {
    const CheckModel m = test::random_check_model(seed, 30, 3);
    const std::uint32_t n = m.matrix.num_states;
    TestRandom random(seed * 104729);
    const StateSet phi = test::random_set(random, n, 80);
    const StateSet psi = test::random_set(random, n, 20);
    const std::vector<ActionIndex> first(n, Scheduler::kAnyAction);
    const Result until =
        modelcheck::until(m.problem(Optimum::kNone), phi, psi, options_for(Mode::kExact, false));
    const std::vector<Rational> naive = test::naive_until(m, first, phi, psi);
    const Result reward = modelcheck::reachability_reward(m.problem(Optimum::kNone), m.rewards, psi,
                                                          options_for(Mode::kExact, false));
    const std::vector<std::optional<Rational>> naive_reward = test::naive_reward(m, first, psi);
    for (std::uint32_t s = 0; s < n; ++s) {
      EXPECT_EQ(until.values[s].exact, naive[s]) << where(seed, Optimum::kNone, s);
      EXPECT_EQ(as_reference(reward.values[s]), naive_reward[s]) << where(seed, Optimum::kNone, s);
    }
  }
}

TEST(ModelcheckRandom, SoundIntervalsContainTheExactValueWithinThePrecision) {
  std::uint64_t checked = 0;
  for (std::uint64_t seed = 1; seed <= kModels; ++seed) {
    const CheckModel m = test::random_check_model(seed, 40, 4);
    const std::uint32_t n = m.matrix.num_states;
    TestRandom random(seed * 31337);
    const StateSet phi = test::random_set(random, n, 85);
    const StateSet psi = test::random_set(random, n, 15);
    for (const Optimum optimum : {Optimum::kNone, Optimum::kMin, Optimum::kMax}) {
      const Result exact =
          modelcheck::until(m.problem(optimum), phi, psi, options_for(Mode::kExact, false));
      const Result sound =
          modelcheck::until(m.problem(optimum), phi, psi, options_for(Mode::kSound, false));
      const Result exact_reward = modelcheck::reachability_reward(
          m.problem(optimum), m.rewards, psi, options_for(Mode::kExact, false));
      const Result sound_reward = modelcheck::reachability_reward(
          m.problem(optimum), m.rewards, psi, options_for(Mode::kSound, false));
      ASSERT_NE(sound.method.find("sound: "), std::string::npos) << sound.method;
      for (std::uint32_t s = 0; s < n; ++s) {
        expect_sound(sound.values[s], exact.values[s], where(seed, optimum, s));
        expect_sound(sound_reward.values[s], exact_reward.values[s],
                     where(seed, optimum, s) + " (reward)");
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, kModels * 3);
}

// The chain the scheduler induces (kAnyAction: the first enabled action) must reproduce the
// value: exactly in exact mode, inside the interval widened by the precision in sound mode
// (the sound mode's scheduler is optimal only up to its precision).
TEST(ModelcheckRandom, TheSchedulersChainHasTheOptimalValue) {
  for (std::uint64_t seed = 1; seed <= kModels; ++seed) {
    const CheckModel m = test::random_check_model(seed, 30, 4);
    const std::uint32_t n = m.matrix.num_states;
    TestRandom random(seed * 65537);
    const StateSet phi = test::random_set(random, n, 85);
    const StateSet psi = test::random_set(random, n, 15);
    for (const Optimum optimum : {Optimum::kMin, Optimum::kMax}) {
      const Result exact =
          modelcheck::until(m.problem(optimum), phi, psi, options_for(Mode::kExact, true));
      ASSERT_TRUE(exact.scheduler.has_value());
      const std::vector<Rational> induced = test::naive_until(m, exact.scheduler->action, phi, psi);
      const Result exact_reward = modelcheck::reachability_reward(
          m.problem(optimum), m.rewards, psi, options_for(Mode::kExact, true));
      const std::vector<std::optional<Rational>> induced_reward =
          test::naive_reward(m, exact_reward.scheduler->action, psi);
      const Result sound =
          modelcheck::until(m.problem(optimum), phi, psi, options_for(Mode::kSound, true));
      const std::vector<Rational> sound_induced =
          test::naive_until(m, sound.scheduler->action, phi, psi);
      for (std::uint32_t s = 0; s < n; ++s) {
        EXPECT_EQ(induced[s], exact.values[s].exact) << where(seed, optimum, s);
        EXPECT_EQ(induced_reward[s], as_reference(exact_reward.values[s]))
            << where(seed, optimum, s) << " (reward)";
        EXPECT_GE(Rational(sound.values[s].upper + kPrecision), sound_induced[s])
            << where(seed, optimum, s) << " (sound)";
        EXPECT_LE(Rational(sound.values[s].lower - kPrecision), sound_induced[s])
            << where(seed, optimum, s) << " (sound)";
      }
    }
  }
}

// The step-dependent scheduler of a bounded property, replayed step by step.
std::vector<Rational> replay_bounded(const CheckModel& m, const Scheduler& scheduler,
                                     const StateSet& phi, const StateSet& psi) {
  const std::uint32_t n = m.matrix.num_states;
  std::vector<Rational> x(n);
  for (std::uint32_t s = 0; s < n; ++s)
    x[s] = psi[s] ? 1 : 0;
  const auto steps = static_cast<std::uint32_t>(scheduler.by_step.size());
  for (std::uint32_t iteration = 1; iteration <= steps; ++iteration) {
    std::vector<Rational> next = x;
    for (std::uint32_t s = 0; s < n; ++s) {
      if (psi[s] || !phi[s]) continue;
      next[s] = 0;
      for (const auto& [t, p] : test::successors(m, s, scheduler.by_step[steps - iteration][s]))
        next[s] += p * x[t];
    }
    x = std::move(next);
  }
  return x;
}

TEST(ModelcheckRandom, BoundedUntilSoundAndExactAgreeAndTheSchedulerReplays) {
  for (std::uint64_t seed = 1; seed <= kModels / 2; ++seed) {
    const CheckModel m = test::random_check_model(seed, 25, 3);
    const std::uint32_t n = m.matrix.num_states;
    TestRandom random(seed * 7);
    const StateSet phi = test::random_set(random, n, 85);
    const StateSet psi = test::random_set(random, n, 15);
    const std::uint32_t steps = random.between(0, 12);
    for (const Optimum optimum : {Optimum::kNone, Optimum::kMin, Optimum::kMax}) {
      const Result exact = modelcheck::bounded_until(m.problem(optimum), phi, psi, steps,
                                                     options_for(Mode::kExact, true));
      const Result sound = modelcheck::bounded_until(m.problem(optimum), phi, psi, steps,
                                                     options_for(Mode::kSound, false));
      std::optional<std::vector<Rational>> replayed;
      if (optimum != Optimum::kNone) {
        EXPECT_EQ(exact.scheduler->by_step.size(), steps);
        replayed = replay_bounded(m, *exact.scheduler, phi, psi);
      }
      for (std::uint32_t s = 0; s < n; ++s) {
        EXPECT_LE(Rational(sound.values[s].lower), exact.values[s].exact)
            << where(seed, optimum, s);
        EXPECT_GE(Rational(sound.values[s].upper), exact.values[s].exact)
            << where(seed, optimum, s);
        EXPECT_LE(sound.values[s].upper - sound.values[s].lower, 1e-12) << where(seed, optimum, s);
        if (replayed) {
          EXPECT_EQ((*replayed)[s], exact.values[s].exact) << where(seed, optimum, s);
        }
      }
    }
  }
}

TEST(ModelcheckRandom, CumulativeRewardsAreSoundAndGrowWithTheSteps) {
  for (std::uint64_t seed = 1; seed <= kModels / 2; ++seed) {
    const CheckModel m = test::random_check_model(seed, 25, 3);
    const std::uint32_t n = m.matrix.num_states;
    for (const Optimum optimum : {Optimum::kMin, Optimum::kMax}) {
      Result previous;
      for (std::uint32_t steps = 0; steps <= 6; ++steps) {
        const Result exact = modelcheck::cumulative_reward(m.problem(optimum), m.rewards, steps,
                                                           options_for(Mode::kExact, false));
        const Result sound = modelcheck::cumulative_reward(m.problem(optimum), m.rewards, steps,
                                                           options_for(Mode::kSound, false));
        for (std::uint32_t s = 0; s < n; ++s) {
          EXPECT_LE(Rational(sound.values[s].lower), exact.values[s].exact);
          EXPECT_GE(Rational(sound.values[s].upper), exact.values[s].exact);
          if (steps > 0) {
            EXPECT_GE(exact.values[s].exact, previous.values[s].exact);
          }
        }
        previous = exact;
      }
    }
  }
}

}  // namespace
}  // namespace oasis
