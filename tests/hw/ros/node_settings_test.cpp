// The node's settings: oasis-go1's schema with the ros: section, read from the YAML that the
// node's ROS parameters become.
#include "ros/node_settings.hpp"

#include <algorithm>

#include <gtest/gtest.h>

namespace oasis::hw::ros_node {
namespace {

std::vector<settings::Diagnostic> problems_of(const std::string& yaml) {
  try {
    parse_node_settings(yaml, "params");
  } catch (const settings::SettingsError& e) {
    return e.diagnostics();
  }
  return {};
}

TEST(NodeSettings, NoParametersAreTheDefaults) {
  const NodeSettings node = parse_node_settings("{}", "params");
  EXPECT_TRUE(node.go1 == settings::default_settings());
  EXPECT_EQ(node.ros.mode, InputMode::kCamera);
  EXPECT_EQ(node.ros.topics.cmd_vel, "cmd_vel");
  EXPECT_EQ(node.ros.input_timeout.count(), 200);
  EXPECT_TRUE(node.ros.use_odom);
}

TEST(NodeSettings, TheRosSectionAndOasisGo1KeysAreRead) {
  const NodeSettings node = parse_node_settings(
      "loop: {rate_hz: 10, controller: paper}\n"
      "ros: {mode: detections, input_timeout_ms: 300, use_odom: false,\n"
      "      topics: {cmd_vel: /base/cmd_vel, detections: people}}\n",
      "params");
  EXPECT_DOUBLE_EQ(node.go1.loop.rate_hz, 10.0);
  EXPECT_EQ(node.go1.loop.controller, "paper");
  EXPECT_EQ(node.ros.mode, InputMode::kDetections);
  EXPECT_EQ(node.ros.input_timeout.count(), 300);
  EXPECT_FALSE(node.ros.use_odom);
  EXPECT_EQ(node.ros.topics.cmd_vel, "/base/cmd_vel");
  EXPECT_EQ(node.ros.topics.detections, "people");
  EXPECT_EQ(node.ros.topics.colour, RosTopics{}.colour);
}

TEST(NodeSettings, EveryBadKeyIsNamedOnce) {
  const std::vector<settings::Diagnostic> problems =
      problems_of("loop: {rate_hz: fast}\nros: {mode: detectoins, input_timeout_ms: 10}\n");
  ASSERT_EQ(problems.size(), 3u);
  EXPECT_EQ(problems[0].key, "loop.rate_hz");
  EXPECT_EQ(problems[1].key, "ros.mode");
  EXPECT_NE(problems[1].message.find("did you mean \"detections\""), std::string::npos);
  EXPECT_EQ(problems[2].key, "ros.input_timeout_ms");
  EXPECT_NE(problems[2].message.find("50..5000"), std::string::npos);
}

TEST(NodeSettings, AnUnknownKeyIsAnErrorWithASuggestion) {
  const std::vector<settings::Diagnostic> problems = problems_of("ros: {topics: {cmdvel: x}}\n");
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].key, "ros.topics.cmdvel");
  EXPECT_NE(problems[0].message.find("cmd_vel"), std::string::npos);
}

TEST(NodeSettings, TheChecksAcrossOasisGo1KeysStillRun) {
  // An action faster than the limits allow is refused here as in go1.yaml.
  const std::vector<settings::Diagnostic> problems =
      problems_of("actions: {forward: {forward: 1.4}}\nlimits: {max_forward: 0.5}\n");
  ASSERT_FALSE(problems.empty());
}

// A topic name ROS would refuse names its parameter, as every other bad key does; the rule is
// the node's (ROS's own names::validate; a stand-in here, which refuses spaces).
TEST(NodeSettings, ATopicNameTheRuleRefusesNamesItsKey) {
  const TopicNameRule no_spaces = [](const std::string& name) {
    return name.find(' ') == std::string::npos;
  };
  std::vector<settings::Diagnostic> problems;
  try {
    parse_node_settings("ros: {topics: {cmd_vel: \"bad name\", odom: \"a b\", colour: ok}}\n",
                        "params", no_spaces);
  } catch (const settings::SettingsError& e) {
    problems = e.diagnostics();
  }
  ASSERT_EQ(problems.size(), 2u);
  const auto cmd_vel = std::find_if(problems.begin(), problems.end(), [](const auto& problem) {
    return problem.key == "ros.topics.cmd_vel";
  });
  ASSERT_NE(cmd_vel, problems.end());
  EXPECT_NE(cmd_vel->message.find("expected a ROS topic name"), std::string::npos);
  EXPECT_NE(cmd_vel->message.find("\"bad name\""), std::string::npos);
  EXPECT_TRUE(problems[0].key == "ros.topics.odom" || problems[1].key == "ros.topics.odom");
  // Without a rule (the settings alone), any non-empty name is taken.
  EXPECT_EQ(
      parse_node_settings("ros: {topics: {cmd_vel: \"bad name\"}}\n", "params").ros.topics.cmd_vel,
      "bad name");
}

}  // namespace
}  // namespace oasis::hw::ros_node
