#pragma once
// Where the loop's velocity commands go, and where the robot's pose comes from. Two kinds:
// the Go1 over UDP (go1_link.hpp: the real robot, or the fake one on loopback) and a dry run
// that sends nothing and integrates its own commands, so that a synthetic world still sees the
// robot move.
#include <optional>
#include <string>

#include "go1/motion_limits.hpp"
#include "go1/planar_pose.hpp"
#include "log/step_record.hpp"

namespace oasis::hw::loop {

class RobotLink {
 public:
  virtual ~RobotLink() = default;

  // A fresh command at loop time `time_s` (seconds since the run started). On the Go1 it feeds
  // the watchdog: a loop that stops calling this stops the robot.
  virtual void command(const go1::VelocityCommand& velocity, double time_s) = 0;

  // The robot's odometry pose (the fake Go1 and the real one report it in HighState).
  virtual go1::Pose pose() const = 0;

  // Stop, then stand, and return when the robot was told so. Idempotent.
  virtual void shut_down() = 0;

  virtual std::string describe() const = 0;

  // What the link has received so far, for the step log; nothing for a link without a robot.
  virtual std::optional<log::LinkRecord> link_record() const { return std::nullopt; }
};

// Sends nothing. The pose follows the commands as a robot without limits or latency would:
// each command holds until the next one's time.
class DryRunLink final : public RobotLink {
 public:
  void command(const go1::VelocityCommand& velocity, double time_s) override;
  go1::Pose pose() const override { return pose_; }
  void shut_down() override { current_ = {}; }
  std::string describe() const override { return "dry run (no packets sent)"; }

 private:
  go1::Pose pose_;
  go1::VelocityCommand current_;
  double current_since_s_ = 0.0;
};

}  // namespace oasis::hw::loop
