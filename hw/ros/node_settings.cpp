#include "ros/node_settings.hpp"

#include <vector>

#include "settings/checks.hpp"
#include "settings/schema.hpp"
#include "settings/settings_visitors.hpp"
#include "yaml_schema/codecs.hpp"
#include "yaml_schema/schema_reader.hpp"

namespace oasis::hw::ros_node {
namespace {

using yaml_schema::BoolCodec;
using yaml_schema::EnumCodec;
using yaml_schema::MillisecondsCodec;
using yaml_schema::TextCodec;

const EnumCodec<InputMode> kModeCodec{
    {{"camera", InputMode::kCamera}, {"detections", InputMode::kDetections}}};

// A topic's name: non-empty and, when a rule is given, valid by it. ROS's own rule (roscpp's
// names::validate) lives in the edge, which the settings may not include; the node passes it.
struct TopicCodec {
  const TopicNameRule* rule = nullptr;
  std::string expected() const {
    return "a ROS topic name (letters, digits, _ and /, beginning with a letter, / or ~)";
  }
  bool parse(std::string_view text, std::string& out) const {
    if (text.empty() || (rule && *rule && !(*rule)(std::string(text)))) return false;
    out = std::string(text);
    return true;
  }
  std::string format(const std::string& value) const { return TextCodec{}.format(value); }
};

// The `ros:` section, in the schema's visitor form (settings/schema.hpp).
template <class V, class S>
void describe_ros(V& v, S& s, const TopicCodec& topic) {
  v.section(
      "ros", "oasis-ros only (hw/ros/README.md): where observations come from and commands go.",
      [&] {
        v.value("mode", s.mode, kModeCodec,
                "camera (images through our perception) or detections (your tracker's output)");
        v.value("input_timeout_ms", s.input_timeout, MillisecondsCodec{50, 5000},
                "no new decision this long after the last one's period: a zero Twist");
        v.value("use_odom", s.use_odom, BoolCodec{},
                "the pose from the odom topic; false: integrate our own commands");
        v.value("base_frame", s.base_frame, TextCodec{}, "REP-105 body frame");
        v.value("odom_frame", s.odom_frame, TextCodec{}, "REP-105 odometry frame");
        v.section("topics", "Topic names, relative to the node's namespace.", [&] {
          v.value("colour", s.topics.colour, topic, "sensor_msgs/Image, bgr8 or rgb8");
          v.value("depth", s.topics.depth, topic, "sensor_msgs/Image, 16UC1 mm or 32FC1 m");
          v.value("camera_info", s.topics.camera_info, topic, "sensor_msgs/CameraInfo");
          v.value("detections", s.topics.detections, topic, "geometry_msgs/PoseArray");
          v.value("reward", s.topics.reward, topic, "std_msgs/Float64");
          v.value("treat_holder", s.topics.treat_holder, topic, "std_msgs/Int8");
          v.value("odom", s.topics.odom, topic, "nav_msgs/Odometry");
          v.value("cmd_vel", s.topics.cmd_vel, topic, "geometry_msgs/Twist");
          v.value("ground_truth", s.topics.ground_truth, topic, "diagnostic_msgs/DiagnosticArray");
        });
      });
}

}  // namespace

NodeSettings parse_node_settings(std::string_view yaml_text, std::string_view origin,
                                 const TopicNameRule& is_topic_name) {
  NodeSettings values;
  const TopicCodec topic{&is_topic_name};
  yaml_schema::parse_with_schema<settings::detail::SettingsVisitors>(
      yaml_text, origin, values,
      [&topic](auto& visitor, auto& node) {
        settings::detail::describe(visitor, node.go1);
        describe_ros(visitor, node.ros, topic);
      },
      [](const NodeSettings& node) { return settings::detail::cross_check(node.go1); },
      "robot:, limits:, actions:, camera:, perception:, loop:, source:, ros:");
  return values;
}

NodeSettings load_node_settings(const std::string& file, const TopicNameRule& is_topic_name) {
  return parse_node_settings(yaml_schema::read_yaml_file(file), file, is_topic_name);
}

std::string to_string(InputMode mode) {
  return kModeCodec.format(mode);
}

}  // namespace oasis::hw::ros_node
