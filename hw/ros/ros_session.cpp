#include "ros/ros_session.hpp"

#include <thread>

#include <ros/master.h>
#include <ros/names.h>
#include <ros/ros.h>
#include <yaml-cpp/yaml.h>

#include "ros/ros_session_handles.hpp"

namespace oasis::hw::ros_node {
namespace {

YAML::Node yaml_of(XmlRpc::XmlRpcValue& value) {
  switch (value.getType()) {
    case XmlRpc::XmlRpcValue::TypeBoolean:
      return YAML::Node(static_cast<bool>(value));
    case XmlRpc::XmlRpcValue::TypeInt:
      return YAML::Node(static_cast<int>(value));
    case XmlRpc::XmlRpcValue::TypeDouble:
      return YAML::Node(static_cast<double>(value));
    case XmlRpc::XmlRpcValue::TypeString:
      return YAML::Node(static_cast<std::string>(value));
    case XmlRpc::XmlRpcValue::TypeArray: {
      YAML::Node list(YAML::NodeType::Sequence);
      for (int k = 0; k < value.size(); ++k)
        list.push_back(yaml_of(value[k]));
      return list;
    }
    case XmlRpc::XmlRpcValue::TypeStruct: {
      YAML::Node map(YAML::NodeType::Map);
      for (auto& member : value)
        map[member.first] = yaml_of(member.second);
      return map;
    }
    default:  // dates, base64: no key of ours takes one; the schema names the key
      return YAML::Node(value.toXml());
  }
}

}  // namespace

std::vector<std::string> arguments_for_cli(int argc, char** argv) {
  std::vector<std::string> arguments;
  for (int k = argc - 1; k >= 1; --k)
    if (std::string(argv[k]).find(":=") == std::string::npos) arguments.emplace_back(argv[k]);
  return arguments;
}

std::string ros_name_problem(const std::string& name) {
  std::string error;
  if (name.empty()) return "an empty name";
  return ros::names::validate(name, error) ? "" : error;
}

RosSession::RosSession(int& argc, char** argv, const std::string& node_name,
                       std::chrono::milliseconds master_timeout)
    : handles_(std::make_unique<RosSessionHandles>()) {
  ros::init(argc, argv, node_name, ros::init_options::NoSigintHandler);
  const auto deadline = std::chrono::steady_clock::now() + master_timeout;
  while (!ros::master::check()) {
    if (std::chrono::steady_clock::now() >= deadline)
      throw RosError("no ROS master at " + ros::master::getURI() + " (ROS_MASTER_URI) within " +
                     std::to_string(master_timeout.count()) +
                     " ms: start roscore, or set ROS_MASTER_URI to the robot's master");
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  handles_->node = std::make_unique<ros::NodeHandle>();
  handles_->private_node = std::make_unique<ros::NodeHandle>("~");
  handles_->spinner = std::make_unique<ros::AsyncSpinner>(1);
  handles_->spinner->start();
}

RosSession::~RosSession() {
  if (ros::isStarted()) shut_down(std::chrono::milliseconds(0));
}

std::string RosSession::private_parameters_yaml() const {
  XmlRpc::XmlRpcValue tree;
  const std::string ns = handles_->private_node->getNamespace();
  if (!ros::param::get(ns, tree) || tree.getType() != XmlRpc::XmlRpcValue::TypeStruct) return "{}";
  YAML::Emitter out;
  out.SetDoublePrecision(17);
  out << yaml_of(tree);
  return out.c_str();
}

std::string RosSession::private_string_parameter(const std::string& name,
                                                 const std::string& fallback) const {
  std::string value;
  if (handles_->private_node->getParam(name, value) && !value.empty()) return value;
  return fallback;
}

std::string RosSession::node_name() const {
  return ros::this_node::getName();
}
std::string RosSession::master_uri() const {
  return ros::master::getURI();
}
bool RosSession::ok() const {
  return ros::ok();
}

void RosSession::shut_down(std::chrono::milliseconds flush) {
  if (!ros::isStarted()) return;
  std::this_thread::sleep_for(flush);
  if (handles_->spinner) handles_->spinner->stop();
  ros::shutdown();
}

}  // namespace oasis::hw::ros_node
