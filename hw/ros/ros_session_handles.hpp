#pragma once
// The ROS side of a RosSession, for the edge's C++17 files only.
#include <memory>

#include <ros/node_handle.h>
#include <ros/spinner.h>

namespace oasis::hw::ros_node {

struct RosSessionHandles {
  std::unique_ptr<ros::NodeHandle> node;          // the node's namespace: topic names resolve here
  std::unique_ptr<ros::NodeHandle> private_node;  // ~: parameters and our own topics
  std::unique_ptr<ros::AsyncSpinner> spinner;     // one thread for every callback
};

}  // namespace oasis::hw::ros_node
