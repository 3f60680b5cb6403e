#pragma once
// The node's connection to ROS: ros::init, the master, the node's handles and the thread that
// runs its subscriptions' callbacks. ROS-free, so that the C++20 mains can hold one; the edge's
// classes reach the handles through ros_session_handles.hpp (C++17, ROS).
//
// Signals. ROS's own SIGINT handler is not installed: the caller installs oasis-go1's stop
// handlers, so that a Ctrl-C ends the loop, the link sends a zero Twist, and only then does the
// node leave the graph.
#include <chrono>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace oasis::hw::ros_node {

class RosError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct RosSessionHandles;  // ros_session_handles.hpp

// A program's own arguments for CLI11's parse(): without the ROS remappings (name:=value,
// _param:=value, __name:=...) that ros::init takes, in the reverse order CLI11 expects.
std::vector<std::string> arguments_for_cli(int argc, char** argv);

// Why `name` is not a valid ROS graph resource name (a topic's), as ROS says it; empty when it
// is one. Needs no master.
std::string ros_name_problem(const std::string& name);

class RosSession {
 public:
  // Joins the graph as `node_name` (remapped by __name:= as usual). Throws RosError when the
  // master (ROS_MASTER_URI) does not answer within `master_timeout`.
  RosSession(int& argc, char** argv, const std::string& node_name,
             std::chrono::milliseconds master_timeout);
  ~RosSession();
  RosSession(const RosSession&) = delete;
  RosSession& operator=(const RosSession&) = delete;

  // The node's private parameters (~...) as one YAML mapping; "{}" when it has none.
  std::string private_parameters_yaml() const;

  // One private string parameter (e.g. "ros/topics/cmd_vel"), if set and a string.
  std::string private_string_parameter(const std::string& name, const std::string& fallback) const;

  std::string node_name() const;
  std::string master_uri() const;
  bool ok() const;  // false once the master told us to go, or after shut_down()

  // Leaves the graph; after a short wait, so that the last messages reach their subscribers.
  void shut_down(std::chrono::milliseconds flush);

  RosSessionHandles& handles() { return *handles_; }

 private:
  std::unique_ptr<RosSessionHandles> handles_;
};

}  // namespace oasis::hw::ros_node
