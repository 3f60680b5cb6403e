// The closed-loop synthetic world: frames follow the robot's pose, the treat follows the
// schedule, and the truth it reports matches the geometry.
#include "loop/synthetic_world.hpp"

#include <cmath>
#include <numbers>
#include <variant>

#include <gtest/gtest.h>

#include "perception/perception.hpp"

namespace oasis::hw::loop {
namespace {

TEST(PlanarPose, FramesRotateTranslateAndInvert) {
  const go1::Pose robot{1.0, 1.0, std::numbers::pi / 2};
  // The robot at (1, 1) facing +y sees (2, 1) one metre to its right.
  const go1::PlanarPoint body = go1::to_body_frame(robot, {2.0, 1.0});
  EXPECT_NEAR(body.x, 0.0, 1e-12);
  EXPECT_NEAR(body.y, -1.0, 1e-12);
  const go1::PlanarPoint back = go1::to_odometry_frame(robot, body);
  EXPECT_NEAR(back.x, 2.0, 1e-12);
  EXPECT_NEAR(back.y, 1.0, 1e-12);
}

TEST(PlanarPose, AdvancedMovesAlongTheHeading) {
  const go1::Pose moved = go1::advanced({0.0, 0.0, std::numbers::pi / 2}, {0.5f, 0.0f, 0.25f}, 2.0);
  EXPECT_NEAR(moved.x, 0.0, 1e-12);
  EXPECT_NEAR(moved.y, 1.0, 1e-12);
  EXPECT_NEAR(moved.yaw, std::numbers::pi / 2 + 0.5, 1e-12);
}

TEST(SyntheticWorld, HolderFollowsTheSchedule) {
  SyntheticWorldSettings settings;
  settings.first_holder = TreatHolder::kHuman2;
  settings.hand_offs = {{1.0, TreatHolder::kHuman1}, {3.0, TreatHolder::kHuman2}};
  const SyntheticWorld world(settings, [] { return go1::Pose{}; });
  EXPECT_EQ(world.holder_at(0.0), TreatHolder::kHuman2);
  EXPECT_EQ(world.holder_at(0.99), TreatHolder::kHuman2);
  EXPECT_EQ(world.holder_at(1.0), TreatHolder::kHuman1);
  EXPECT_EQ(world.holder_at(5.0), TreatHolder::kHuman2);
}

TEST(SyntheticWorld, FramesFollowThePoseAndPerceptionFindsThePeople) {
  go1::Pose robot;
  SyntheticWorldSettings settings;
  settings.hand_offs.clear();
  SyntheticWorld world(settings, [&robot] { return robot; });
  Perception perception;

  NextFrame first = world.next();
  ASSERT_TRUE(std::holds_alternative<Frame>(first));
  const PerceptionResult at_start = perception.step(std::get<Frame>(first));
  ASSERT_TRUE(at_start.humans[0].seen);
  EXPECT_NEAR(at_start.humans[0].x_m, 2.5, 0.15);
  EXPECT_NEAR(at_start.humans[0].y_m, 0.7, 0.15);
  EXPECT_EQ(at_start.holder, TreatHolder::kHuman1);
  ASSERT_TRUE(world.truth_of_last_frame().has_value());
  EXPECT_FALSE(world.truth_of_last_frame()->holder_in_reach);

  // Walk up to human 1: 1.9 m forward and 0.7 m left puts them 0.6 m straight ahead.
  robot = {1.9, 0.7, 0.0};
  NextFrame second = world.next();
  ASSERT_TRUE(std::holds_alternative<Frame>(second));
  EXPECT_DOUBLE_EQ(std::get<Frame>(second).timestamp_s, settings.period_s);
  const PerceptionResult close = perception.step(std::get<Frame>(second));
  ASSERT_TRUE(close.humans[0].seen);
  EXPECT_NEAR(close.humans[0].x_m, 0.6, 0.1);
  EXPECT_NEAR(close.humans[0].y_m, 0.0, 0.1);
  EXPECT_TRUE(world.truth_of_last_frame()->holder_in_reach);
  EXPECT_EQ(close.reward, 1.0);
}

TEST(SyntheticWorld, RefusesAMissingPoseProvider) {
  EXPECT_THROW(SyntheticWorld({}, nullptr), std::invalid_argument);
}

}  // namespace
}  // namespace oasis::hw::loop
