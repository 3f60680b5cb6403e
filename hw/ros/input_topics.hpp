#pragma once
// Where oasis-ros's observations come from and its commands go: the input mode and the topic
// names (the ros: section of the node's settings, node_settings.hpp). Plain C++17, for the
// ROS edge too.
#include <string>

namespace oasis::hw::ros_node {

// Where the loop's observations come from.
enum class InputMode {
  kCamera,      // colour + depth images and the camera's intrinsics, run through our perception
  kDetections,  // the robot's own tracker: one position per catalog object, and the reward
};

struct RosTopics {
  std::string colour = "camera/color/image_raw";
  std::string depth = "camera/aligned_depth_to_color/image_raw";  // registered to the colour
  std::string camera_info = "camera/color/camera_info";
  std::string detections = "detections";      // geometry_msgs/PoseArray, base frame
  std::string reward = "reward";              // std_msgs/Float64, optional
  std::string treat_holder = "treat_holder";  // std_msgs/Int8: 0 nobody, 1 or 2; optional
  std::string odom = "odom";                  // nav_msgs/Odometry
  std::string cmd_vel = "cmd_vel";            // geometry_msgs/Twist
  std::string ground_truth = "ground_truth";  // diagnostic_msgs/DiagnosticArray, optional
};

}  // namespace oasis::hw::ros_node
