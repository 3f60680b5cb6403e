#pragma once
// The robot's planar pose in the odometry frame, how a body-frame velocity moves it, and the
// change of frame between the two. The
// fake Go1 integrates the commands it receives with this, and so does a dry run, which has no
// robot to ask: both must agree on what a command does.
#include <cmath>

#include "go1/motion_limits.hpp"

namespace oasis::hw::go1 {

struct Pose {
  double x = 0.0;    // m
  double y = 0.0;    // m
  double yaw = 0.0;  // rad, counter-clockwise from the odometry frame's x axis
};

// The pose after `seconds` at body velocity `velocity`, heading held at its start value (an
// Euler step: callers integrate in steps of a few milliseconds, or of one 0.2 s control period
// when that is all they know).
inline Pose advanced(Pose pose, const VelocityCommand& velocity, double seconds) {
  const double forward = velocity.forward;
  const double lateral = velocity.lateral;
  pose.x += (forward * std::cos(pose.yaw) - lateral * std::sin(pose.yaw)) * seconds;
  pose.y += (forward * std::sin(pose.yaw) + lateral * std::cos(pose.yaw)) * seconds;
  pose.yaw += velocity.yaw_rate * seconds;
  return pose;
}

struct PlanarPoint {
  double x = 0.0;  // m
  double y = 0.0;  // m
};

// An odometry-frame point as the robot at `robot` sees it: x forward, y left.
inline PlanarPoint to_body_frame(const Pose& robot, const PlanarPoint& odometry) {
  const double dx = odometry.x - robot.x;
  const double dy = odometry.y - robot.y;
  const double c = std::cos(robot.yaw);
  const double s = std::sin(robot.yaw);
  return {c * dx + s * dy, -s * dx + c * dy};
}

// The inverse: a body-frame point of the robot at `robot` in the odometry frame.
inline PlanarPoint to_odometry_frame(const Pose& robot, const PlanarPoint& body) {
  const double c = std::cos(robot.yaw);
  const double s = std::sin(robot.yaw);
  return {robot.x + c * body.x - s * body.y, robot.y + s * body.x + c * body.y};
}

}  // namespace oasis::hw::go1
