#pragma once
// Every Twist oasis-ros publishes on cmd_vel passes here (the edge's C++17 files only). Once
// the last resort fired (last_resort_stop.hpp), a moving Twist is dropped: a thread still
// running - the link's repeater, the loop - cannot follow the last resort's zero Twist with a
// moving one. The check and the publish are one step under a lock that the last resort takes
// before it halts, so no moving Twist that passed the check can be published after the zero.
#include <geometry_msgs/Twist.h>
#include <ros/publisher.h>

namespace oasis::hw::ros_node {

// Publishes `twist` on `publisher`, unless the commands are halted and it is not zero.
void publish_command(const ros::Publisher& publisher, const geometry_msgs::Twist& twist);

}  // namespace oasis::hw::ros_node
