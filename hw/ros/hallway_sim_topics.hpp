#pragma once
// The ROS side of oasis-ros-hallway-sim (hallway_sim_node.cpp): each frame's
// messages out - odom, ground_truth, the camera's info, depth and colour, in
// that order and with one stamp - the latest cmd_vel in, and, if asked, every
// message published written to a rosbag as well. ROS-free header, so that the
// C++20 main can hold one.
//
// The bag goes to BAG.tmp and becomes BAG only in close_bag(), so BAG is never
// a half-written file; a bag never closed that way (an error) is closed by the
// destructor and left at BAG.tmp.
#include <cstdint>
#include <memory>
#include <string>

#include "go1/motion_limits.hpp"
#include "go1/planar_pose.hpp"
#include "perception/frame.hpp"
#include "ros/input_topics.hpp"
#include "ros/ros_session.hpp"

namespace oasis::hw::ros_node {

struct HallwaySimTopicOptions {
  RosTopics topics;                      // odom, ground_truth, camera_info, depth and colour out;
                                         // cmd_vel in
  std::string odom_frame = "odom";       // REP-105
  std::string base_frame = "base_link";  // REP-105
  std::string optical_frame = "camera_color_optical_frame";  // realsense2_camera's name
  std::string bag;                                           // empty: no bag
};

class HallwaySimTopics {
 public:
  // Advertises, subscribes and opens the bag. Throws RosError when the bag
  // cannot be written.
  HallwaySimTopics(RosSession& session, HallwaySimTopicOptions options);
  ~HallwaySimTopics();
  HallwaySimTopics(const HallwaySimTopics&) = delete;
  HallwaySimTopics& operator=(const HallwaySimTopics&) = delete;

  // The latest cmd_vel received: zero before the first. A Twist with a
  // linear.x, linear.y or angular.z that is not finite is refused (counted, and
  // the one before it stays).
  go1::VelocityCommand latest_command() const;
  std::uint64_t commands_received() const;
  std::uint64_t commands_refused() const;

  std::uint32_t colour_subscribers() const;
  std::string colour_topic() const;   // resolved, as ROS names it
  std::string cmd_vel_topic() const;  // resolved

  // Publishes one frame's five messages stamped ros::Time::now() (returned, in
  // seconds) and writes them to the bag under the topic names of the options,
  // without a leading slash. `frame` must have depth in millimetres;
  // `context_name` and `reward` are the ground truth.
  double publish(const Frame& frame, const go1::Pose& robot, const go1::VelocityCommand& velocity,
                 const std::string& context_name, double reward);

  // Closes the bag and renames BAG.tmp to BAG; nothing without a bag, or a
  // second time. Throws RosError when the rename fails.
  void close_bag();
  std::string bag_path() const;  // empty without a bag
  std::uint64_t bag_messages() const;

  struct State;  // hallway_sim_topics.cpp

 private:
  std::unique_ptr<State> state_;
};

}  // namespace oasis::hw::ros_node
