#pragma once
// The loop's robot link over ROS: each decision goes out as a geometry_msgs/Twist on cmd_vel,
// mapped from the catalog's action through the velocity table, as the Go1 link sends it.
//
// The fail-safe, as the Go1 sender's watchdog (hw/go1/README.md): a decision is repeated every
// `keepalive` while it is current, that is for one control period after it was made plus
// `input_timeout` for a late frame. Past that, no fresh input has come: the link publishes a
// zero Twist, and repeats it every keepalive until a decision comes again. shut_down() (the end
// of the loop, a signal, an error) publishes a zero Twist before it returns. The node never
// leaves the robot moving on an old command. ROS-free header.
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "go1/watchdog.hpp"
#include "loop/robot_link.hpp"
#include "ros/ros_session.hpp"

namespace oasis::hw::ros_node {

struct CmdVelOptions {
  std::string topic = "cmd_vel";
  double period_s = 0.2;                    // the loop's control period
  std::chrono::milliseconds keepalive{50};  // loop.keepalive_ms
  std::chrono::milliseconds input_timeout = go1::kDefaultWatchdogTimeout;  // ros.input_timeout_ms
};

class CmdVelLink final : public loop::RobotLink {
 public:
  // `odometry`: the robot's pose when the frame being decided on was taken; when it returns
  // nothing (no odometry, or use_odom off), the link integrates its own commands, as a dry run.
  CmdVelLink(RosSession& session, CmdVelOptions options,
             std::function<std::optional<go1::Pose>()> odometry);
  ~CmdVelLink() override;

  void command(const go1::VelocityCommand& velocity, double time_s) override;
  go1::Pose pose() const override;
  void shut_down() override;
  std::string describe() const override;

  // How often the fail-safe stopped the robot (each time until the next decision counts once).
  std::uint64_t fail_safe_stops() const;

  // Publishes one zero Twist on `topic` for a node that stops before the link could be set up
  // (a bad parameter): it waits up to `wait` for a subscriber, so the message is not lost.
  static void send_zero_once(RosSession& session, const std::string& topic,
                             std::chrono::milliseconds wait);

  struct State;  // cmd_vel_link.cpp

 private:
  std::unique_ptr<State> state_;
};

}  // namespace oasis::hw::ros_node
