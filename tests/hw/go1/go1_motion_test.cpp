// Clamps, ramp, the watchdog rule as a function of time, the loss model's determinism.

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "go1/loss_model.hpp"
#include "go1/motion_limits.hpp"
#include "go1/watchdog.hpp"

namespace oasis::hw::go1 {
namespace {

using std::chrono::milliseconds;

TEST(Go1Clamp, LimitsEachComponentBothWays) {
  const MotionLimits limits;  // forward 0.5, backward 0.3, lateral 0.3, yaw 1.0
  EXPECT_EQ(clamp_to_limits({2.0f, 1.0f, 5.0f}, limits), (VelocityCommand{0.5f, 0.3f, 1.0f}));
  EXPECT_EQ(clamp_to_limits({-2.0f, -1.0f, -5.0f}, limits), (VelocityCommand{-0.3f, -0.3f, -1.0f}));
  EXPECT_EQ(clamp_to_limits({0.1f, -0.1f, 0.2f}, limits), (VelocityCommand{0.1f, -0.1f, 0.2f}));
}

TEST(Go1Clamp, NonFiniteBecomesZero) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  EXPECT_EQ(clamp_to_limits({nan, inf, -inf}, MotionLimits{}), VelocityCommand{});
}

TEST(Go1Clamp, LimitsBeyondTheDocumentedTrotRangeAreRefused) {
  EXPECT_EQ(check_limits(MotionLimits{}), "");
  MotionLimits too_fast;
  too_fast.max_forward = 2.0f;
  EXPECT_NE(check_limits(too_fast), "");
  MotionLimits no_ramp;
  no_ramp.max_linear_acceleration = 0.0f;
  EXPECT_NE(check_limits(no_ramp), "");
}

TEST(Go1Ramp, MovesAtMostOneStepPerTick) {
  MotionLimits limits;
  limits.max_linear_acceleration = 1.0f;  // 0.01 m/s per 10 ms tick
  limits.max_yaw_acceleration = 2.0f;     // 0.02 rad/s per tick
  VelocityCommand current;
  const VelocityCommand target{0.5f, -0.015f, 1.0f};
  current = ramp_toward(current, target, limits, 0.01f);
  EXPECT_NEAR(current.forward, 0.01f, 1e-6);
  EXPECT_NEAR(current.lateral, -0.01f, 1e-6);
  EXPECT_NEAR(current.yaw_rate, 0.02f, 1e-6);
  current = ramp_toward(current, target, limits, 0.01f);
  EXPECT_NEAR(current.lateral, -0.015f, 1e-6);  // reached, not overshot
  for (int tick = 0; tick < 100; ++tick)
    current = ramp_toward(current, target, limits, 0.01f);
  EXPECT_EQ(current, target);
}

TEST(Go1Watchdog, StandsBeforeTheFirstCommandThenPassesStopsAndStands) {
  using Clock = Watchdog::Clock;
  const Clock::time_point start{};
  Watchdog watchdog(milliseconds(200), milliseconds(300));
  EXPECT_EQ(watchdog.decide(start), SafetyAction::kStand);
  watchdog.feed(start);
  EXPECT_EQ(watchdog.decide(start + milliseconds(199)), SafetyAction::kPass);
  EXPECT_EQ(watchdog.decide(start + milliseconds(200)), SafetyAction::kStop);
  EXPECT_EQ(watchdog.decide(start + milliseconds(499)), SafetyAction::kStop);
  EXPECT_EQ(watchdog.decide(start + milliseconds(500)), SafetyAction::kStand);
  watchdog.feed(start + milliseconds(600));
  EXPECT_EQ(watchdog.decide(start + milliseconds(601)), SafetyAction::kPass);
}

TEST(Go1LossModel, SameSeedSameDropsAndAboutTheAskedRate) {
  LossModel first(0.2, 42), second(0.2, 42), other(0.2, 43);
  int dropped = 0, differences = 0;
  for (int i = 0; i < 10000; ++i) {
    const bool drop = first.drop_next();
    EXPECT_EQ(drop, second.drop_next());
    differences += drop != other.drop_next();
    dropped += drop;
  }
  EXPECT_NEAR(dropped / 10000.0, 0.2, 0.02);
  EXPECT_GT(differences, 0);
  LossModel never(0.0, 1), always(1.0, 1);
  EXPECT_FALSE(never.drop_next());
  EXPECT_TRUE(always.drop_next());
}

}  // namespace
}  // namespace oasis::hw::go1
