#pragma once
// The error line of the ROS programs (oasis-ros, oasis-ros-hallway-sim): "PROGRAM: error:
// MESSAGE" on stderr, the format every program of oasis reports in (the compiler's). Every
// error that ends them is printed through it; only the last-resort handler
// (last_resort_stop.cpp) words its own line, "oasis-ros: internal error: ...", as what it
// reports is a bug, not a problem with the input.
#include <iostream>
#include <string_view>

namespace oasis::hw::ros_node {

inline void print_error(std::string_view program, std::string_view message) {
  std::cerr << program << ": error: " << message << '\n';
}

}  // namespace oasis::hw::ros_node
