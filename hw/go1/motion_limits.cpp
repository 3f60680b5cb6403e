#include "go1/motion_limits.hpp"

#include <algorithm>
#include <cmath>

namespace oasis::hw::go1 {

namespace {

// Trot-gait ranges from the comm.h comments (FACTS §1).
constexpr float kDocumentedMaxForward = 1.5f;
constexpr float kDocumentedMaxBackward = 1.1f;
constexpr float kDocumentedMaxLateral = 1.0f;
constexpr float kDocumentedMaxYawRate = 4.0f;

bool within(float value, float documented_max) {
  return std::isfinite(value) && value >= 0.0f && value <= documented_max;
}

float step_toward(float current, float target, float max_step) {
  return current + std::clamp(target - current, -max_step, max_step);
}

// NaN would pass std::clamp unchanged; a command we cannot read is a command to stand still.
float finite_or_zero(float value) {
  return std::isfinite(value) ? value : 0.0f;
}

}  // namespace

std::string check_limits(const MotionLimits& limits) {
  if (!within(limits.max_forward, kDocumentedMaxForward))
    return "max_forward must be in 0..1.5 m/s (the documented trot range)";
  if (!within(limits.max_backward, kDocumentedMaxBackward))
    return "max_backward must be in 0..1.1 m/s (the documented trot range)";
  if (!within(limits.max_lateral, kDocumentedMaxLateral))
    return "max_lateral must be in 0..1.0 m/s (the documented trot range)";
  if (!within(limits.max_yaw_rate, kDocumentedMaxYawRate))
    return "max_yaw_rate must be in 0..4.0 rad/s (the documented trot range)";
  if (!(limits.max_linear_acceleration > 0.0f) || !std::isfinite(limits.max_linear_acceleration))
    return "max_linear_acceleration must be positive";
  if (!(limits.max_yaw_acceleration > 0.0f) || !std::isfinite(limits.max_yaw_acceleration))
    return "max_yaw_acceleration must be positive";
  return {};
}

VelocityCommand clamp_to_limits(const VelocityCommand& wanted, const MotionLimits& limits) {
  return VelocityCommand{
      std::clamp(finite_or_zero(wanted.forward), -limits.max_backward, limits.max_forward),
      std::clamp(finite_or_zero(wanted.lateral), -limits.max_lateral, limits.max_lateral),
      std::clamp(finite_or_zero(wanted.yaw_rate), -limits.max_yaw_rate, limits.max_yaw_rate)};
}

VelocityCommand ramp_toward(const VelocityCommand& current, const VelocityCommand& target,
                            const MotionLimits& limits, float tick_seconds) {
  const float linear_step = limits.max_linear_acceleration * tick_seconds;
  const float yaw_step = limits.max_yaw_acceleration * tick_seconds;
  return VelocityCommand{step_toward(current.forward, target.forward, linear_step),
                         step_toward(current.lateral, target.lateral, linear_step),
                         step_toward(current.yaw_rate, target.yaw_rate, yaw_step)};
}

}  // namespace oasis::hw::go1
