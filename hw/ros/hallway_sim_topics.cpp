#include "ros/hallway_sim_topics.hpp"

#include <cmath>
#include <filesystem>
#include <mutex>
#include <optional>
#include <system_error>
#include <utility>

#include <diagnostic_msgs/DiagnosticArray.h>
#include <geometry_msgs/Twist.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <rosbag/bag.h>
#include <rosbag/exceptions.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>

#include "ros/message_conversion.hpp"
#include "ros/ros_session_handles.hpp"

namespace oasis::hw::ros_node {
namespace {

constexpr std::uint32_t kQueue = 5;  // images are large: a slow subscriber loses old ones

// A topic's name in the bag: as published, relative.
std::string bag_topic(const std::string& topic) {
  return !topic.empty() && topic.front() == '/' ? topic.substr(1) : topic;
}

}  // namespace

struct HallwaySimTopics::State {
  HallwaySimTopicOptions options;
  ros::Publisher odom;
  ros::Publisher truth;
  ros::Publisher info;
  ros::Publisher depth;
  ros::Publisher colour;
  ros::Subscriber cmd_vel;

  mutable std::mutex mutex;  // the command, written by the spinner's thread
  go1::VelocityCommand latest;
  std::uint64_t received = 0;
  std::uint64_t refused = 0;

  std::optional<rosbag::Bag> bag;  // open until close_bag()
  std::uint64_t bag_messages = 0;

  void receive(const geometry_msgs::Twist& twist) {
    const bool finite = std::isfinite(twist.linear.x) && std::isfinite(twist.linear.y) &&
                        std::isfinite(twist.angular.z);
    std::lock_guard<std::mutex> lock(mutex);
    if (!finite) {
      ++refused;
      ROS_WARN_THROTTLE(5.0, "oasis-ros-hallway-sim: a cmd_vel that is not finite, ignored");
      return;
    }
    latest = velocity_from_twist(twist);
    ++received;
  }

  template <class Message>
  void send(const ros::Publisher& publisher, const std::string& topic, const ros::Time& stamp,
            const Message& message) {
    publisher.publish(message);
    if (!bag) return;
    bag->write(bag_topic(topic), stamp, message);
    ++bag_messages;
  }
};

HallwaySimTopics::HallwaySimTopics(RosSession& session, HallwaySimTopicOptions options)
    : state_(std::make_unique<State>()) {
  State& s = *state_;
  s.options = std::move(options);
  if (!s.options.bag.empty()) {
    s.bag.emplace();
    try {
      s.bag->open(s.options.bag + ".tmp", rosbag::bagmode::Write);
    } catch (const rosbag::BagException& e) {
      throw RosError("--bag: cannot write " + s.options.bag + ".tmp: " + e.what());
    }
  }
  ros::NodeHandle& node = *session.handles().node;
  const RosTopics& topics = s.options.topics;
  s.odom = node.advertise<nav_msgs::Odometry>(topics.odom, kQueue);
  s.truth = node.advertise<diagnostic_msgs::DiagnosticArray>(topics.ground_truth, kQueue);
  s.info = node.advertise<sensor_msgs::CameraInfo>(topics.camera_info, kQueue);
  s.depth = node.advertise<sensor_msgs::Image>(topics.depth, kQueue);
  s.colour = node.advertise<sensor_msgs::Image>(topics.colour, kQueue);
  s.cmd_vel = node.subscribe<geometry_msgs::Twist>(
      topics.cmd_vel, 10, [state = state_.get()](const geometry_msgs::Twist::ConstPtr& twist) {
        state->receive(*twist);
      });
}

HallwaySimTopics::~HallwaySimTopics() {
  // Unsubscribe first: the spinner's thread may not call into a State being
  // destroyed.
  state_->cmd_vel.shutdown();
}

go1::VelocityCommand HallwaySimTopics::latest_command() const {
  std::lock_guard<std::mutex> lock(state_->mutex);
  return state_->latest;
}

std::uint64_t HallwaySimTopics::commands_received() const {
  std::lock_guard<std::mutex> lock(state_->mutex);
  return state_->received;
}

std::uint64_t HallwaySimTopics::commands_refused() const {
  std::lock_guard<std::mutex> lock(state_->mutex);
  return state_->refused;
}

std::uint32_t HallwaySimTopics::colour_subscribers() const {
  return state_->colour.getNumSubscribers();
}

std::string HallwaySimTopics::colour_topic() const {
  return state_->colour.getTopic();
}
std::string HallwaySimTopics::cmd_vel_topic() const {
  return state_->cmd_vel.getTopic();
}

double HallwaySimTopics::publish(const Frame& frame, const go1::Pose& robot,
                                 const go1::VelocityCommand& velocity,
                                 const std::string& context_name, double reward) {
  State& s = *state_;
  const ros::Time stamp = ros::Time::now();
  const CameraMessages camera = messages_from_frame(frame, stamp, s.options.optical_frame);
  const RosTopics& topics = s.options.topics;
  s.send(s.odom, topics.odom, stamp,
         odometry_from_pose(robot, velocity, stamp, s.options.odom_frame, s.options.base_frame));
  s.send(s.truth, topics.ground_truth, stamp, truth_message(context_name, reward, stamp));
  s.send(s.info, topics.camera_info, stamp, camera.info);
  s.send(s.depth, topics.depth, stamp, camera.depth);
  s.send(s.colour, topics.colour, stamp, camera.colour);
  return stamp.toSec();
}

void HallwaySimTopics::close_bag() {
  State& s = *state_;
  if (!s.bag) return;
  s.bag->close();
  s.bag.reset();
  const std::string temporary = s.options.bag + ".tmp";
  std::error_code error;
  std::filesystem::rename(temporary, s.options.bag, error);
  if (error)
    throw RosError("--bag: cannot rename " + temporary + " to " + s.options.bag + ": " +
                   error.message());
}

std::string HallwaySimTopics::bag_path() const {
  return state_->options.bag;
}
std::uint64_t HallwaySimTopics::bag_messages() const {
  return state_->bag_messages;
}

}  // namespace oasis::hw::ros_node
