#pragma once
// What the sender lets through: a velocity command clamped to limits, then ramped toward at a
// bounded change per tick so that an operator's (or a policy's) step becomes a slope.

#include <string>

namespace oasis::hw::go1 {

struct VelocityCommand {
  float forward = 0.0f;   // m/s, body frame, + ahead
  float lateral = 0.0f;   // m/s, body frame, + left
  float yaw_rate = 0.0f;  // rad/s, + counter-clockwise

  // Written out, not defaulted: hw/ros's ROS-facing files include this and compile as C++17
  // (ROS 1's message headers do not compile as C++20).
  bool operator==(const VelocityCommand& other) const {
    return forward == other.forward && lateral == other.lateral && yaw_rate == other.yaw_rate;
  }
  bool operator!=(const VelocityCommand& other) const { return !(*this == other); }
};

// Defaults are conservative indoor values, well inside the trot ranges comm.h documents
// (vx -1.1..1.5, vy -1.0..1.0 m/s, yaw -4..4 rad/s; FACTS §1 "Documented ranges").
struct MotionLimits {
  float max_forward = 0.5f;              // m/s
  float max_backward = 0.3f;             // m/s, a magnitude
  float max_lateral = 0.3f;              // m/s, either side
  float max_yaw_rate = 1.0f;             // rad/s, either way
  float max_linear_acceleration = 1.0f;  // m/s^2: the ramp, per tick = this / rate
  float max_yaw_acceleration = 3.0f;     // rad/s^2
};

// An empty string if the limits are usable: positive, and within the documented trot ranges.
std::string check_limits(const MotionLimits& limits);

VelocityCommand clamp_to_limits(const VelocityCommand& wanted, const MotionLimits& limits);

// One tick of the ramp: each component moves from `current` toward `target` by at most
// acceleration * tick_seconds.
VelocityCommand ramp_toward(const VelocityCommand& current, const VelocityCommand& target,
                            const MotionLimits& limits, float tick_seconds);

}  // namespace oasis::hw::go1
