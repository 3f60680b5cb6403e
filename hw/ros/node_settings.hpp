#pragma once
// The settings of oasis-ros: oasis-go1's (settings.hpp: the catalog, the controller profile, the
// action velocities, the loop rate, perception, the camera mount) plus a `ros:` section for the
// node's own edges (the input mode, the topic names, the fail-safe's timeout, the frames).
//
// One schema, not two: the node reads its private ROS parameters (~loop/rate_hz,
// ~ros/mode, ...) as one tree and walks the very describe() of oasis-go1's YAML file over it,
// with the `ros:` section added, so a key has the same name, type, range and error message in
// hw/config/go1.yaml, in a rosparam file and on a roslaunch command line. The robot:, limits:
// and source: sections are accepted for that reason, and unused: the node drives cmd_vel, and
// its frames come from topics.
#include <chrono>
#include <functional>
#include <string>
#include <string_view>

#include "go1/watchdog.hpp"
#include "ros/input_topics.hpp"
#include "settings/settings.hpp"

namespace oasis::hw::ros_node {

struct RosSettings {
  InputMode mode = InputMode::kCamera;
  RosTopics topics;
  // The fail-safe: a decision is repeated on cmd_vel every loop.keepalive_ms for one control
  // period; when no new one comes for this long after that, the node publishes a zero Twist
  // (and repeats it), as the Go1 sender's watchdog stops the robot go1::kDefaultWatchdogTimeout
  // after the loop stalls.
  std::chrono::milliseconds input_timeout = go1::kDefaultWatchdogTimeout;
  // True: the robot's pose comes from `topics.odom` (needed to hold an unseen person's place
  // while the robot moves). False: the node integrates its own commands, as a dry run does.
  bool use_odom = true;
  std::string base_frame = "base_link";  // REP-105: the robot's body, x forward, y left
  std::string odom_frame = "odom";       // REP-105: the odometry frame the markers are drawn in
};

struct NodeSettings {
  settings::Go1Settings go1 = settings::default_settings();
  RosSettings ros;
};

// Whether a text is a valid ROS topic name. The node gives ROS's own rule (ros_session.hpp);
// without one, any non-empty text is taken.
using TopicNameRule = std::function<bool(const std::string&)>;

// Parses the node's parameter tree, as YAML text (the ROS parameters converted, or a file).
// `origin` names it in messages. Throws settings::SettingsError with every problem found, each
// naming its key ("loop.rate_hz", "ros.mode", "ros.topics.cmd_vel" for a name `is_topic_name`
// refuses), so that no bad name reaches ROS, whose own error would name no parameter.
NodeSettings parse_node_settings(std::string_view yaml_text, std::string_view origin,
                                 const TopicNameRule& is_topic_name = {});

// The same from a YAML file (oasis-ros --bag --params FILE). Throws settings::SettingsError.
NodeSettings load_node_settings(const std::string& file, const TopicNameRule& is_topic_name = {});

// "camera" or "detections".
std::string to_string(InputMode mode);

}  // namespace oasis::hw::ros_node
