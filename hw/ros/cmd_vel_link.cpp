#include "ros/cmd_vel_link.hpp"

#include <atomic>
#include <condition_variable>
#include <mutex>
#include <thread>

#include <geometry_msgs/Twist.h>
#include <ros/ros.h>

#include "ros/command_gate.hpp"
#include "ros/message_conversion.hpp"
#include "ros/ros_session_handles.hpp"

namespace oasis::hw::ros_node {
namespace {

using Clock = std::chrono::steady_clock;

}  // namespace

struct CmdVelLink::State {
  CmdVelOptions options;
  std::function<std::optional<go1::Pose>()> odometry;
  ros::Publisher publisher;

  mutable std::mutex mutex;
  std::condition_variable wake;
  bool stopping = false;
  std::optional<Clock::time_point> last_decision;
  go1::VelocityCommand current;
  loop::DryRunLink integrated;  // the pose when there is no odometry
  std::uint64_t fail_safe_stops = 0;
  bool stopped_by_fail_safe = false;
  std::thread repeater;

  void publish(const go1::VelocityCommand& velocity) {
    publish_command(publisher, twist_from_velocity(velocity));
  }

  // Every keepalive: the current decision while it is fresh, a zero Twist once it is not.
  void repeat() {
    const auto fresh_for = std::chrono::duration_cast<Clock::duration>(
                               std::chrono::duration<double>(options.period_s)) +
                           options.input_timeout;
    std::unique_lock<std::mutex> lock(mutex);
    while (!stopping) {
      wake.wait_for(lock, options.keepalive);
      if (stopping || !last_decision) continue;
      if (Clock::now() - *last_decision <= fresh_for) {
        publish(current);
        continue;
      }
      if (!stopped_by_fail_safe) {
        ROS_WARN(
            "oasis-ros: no fresh input for %lld ms after the last decision's period: "
            "zero Twist until the next decision",
            static_cast<long long>(options.input_timeout.count()));
        ++fail_safe_stops;
      }
      stopped_by_fail_safe = true;
      publish({});
    }
  }
};

CmdVelLink::CmdVelLink(RosSession& session, CmdVelOptions options,
                       std::function<std::optional<go1::Pose>()> odometry)
    : state_(std::make_unique<State>()) {
  state_->options = std::move(options);
  state_->odometry = std::move(odometry);
  state_->publisher =
      session.handles().node->advertise<geometry_msgs::Twist>(state_->options.topic, 10);
  state_->repeater = std::thread([state = state_.get()] { state->repeat(); });
}

CmdVelLink::~CmdVelLink() {
  shut_down();
}

void CmdVelLink::command(const go1::VelocityCommand& velocity, double time_s) {
  std::lock_guard<std::mutex> lock(state_->mutex);
  if (state_->stopping) return;
  state_->current = velocity;
  state_->last_decision = Clock::now();
  state_->stopped_by_fail_safe = false;
  state_->integrated.command(velocity, time_s);
  state_->publish(velocity);
}

go1::Pose CmdVelLink::pose() const {
  if (state_->odometry)
    if (const std::optional<go1::Pose> pose = state_->odometry()) return *pose;
  std::lock_guard<std::mutex> lock(state_->mutex);
  return state_->integrated.pose();
}

void CmdVelLink::shut_down() {
  {
    std::lock_guard<std::mutex> lock(state_->mutex);
    if (state_->stopping) return;
    state_->stopping = true;
    state_->current = {};
  }
  state_->wake.notify_all();
  if (state_->repeater.joinable()) state_->repeater.join();
  // Three zero Twists 20 ms apart: one lost on the way must not leave the robot walking.
  for (int k = 0; k < 3; ++k) {
    state_->publish({});
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

std::string CmdVelLink::describe() const {
  return "cmd_vel " + ros::NodeHandle().resolveName(state_->options.topic) +
         " (geometry_msgs/Twist; zero after " +
         std::to_string(state_->options.input_timeout.count()) + " ms without fresh input)";
}

std::uint64_t CmdVelLink::fail_safe_stops() const {
  std::lock_guard<std::mutex> lock(state_->mutex);
  return state_->fail_safe_stops;
}

void CmdVelLink::send_zero_once(RosSession& session, const std::string& topic,
                                std::chrono::milliseconds wait) {
  // Latched: a subscriber that connects after the publish, but before the node leaves, still
  // gets it.
  ros::Publisher publisher =
      session.handles().node->advertise<geometry_msgs::Twist>(topic, 1, /*latch=*/true);
  publisher.publish(geometry_msgs::Twist());
  const auto deadline = Clock::now() + wait;
  while (publisher.getNumSubscribers() == 0 && Clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
}

}  // namespace oasis::hw::ros_node
