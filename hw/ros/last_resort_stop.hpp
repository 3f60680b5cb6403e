#pragma once
// The last resort of oasis-ros's fail-safe: when the node dies of something nobody handled, a
// zero Twist still goes out on cmd_vel before the process ends. ROS-free header.
//
// What it covers, once armed:
//   - an exception that reaches std::terminate (thrown in the loop, in a ROS callback, in the
//     link's repeater thread, or through a noexcept function): the terminate handler runs in
//     the thread that threw, an ordinary context, and publishes three zero Twists 20 ms apart
//     through roscpp, waits 100 ms for them to leave, prints what was thrown, then aborts;
//   - SIGSEGV, SIGBUS, SIGFPE, SIGILL and SIGABRT, best effort: a signal handler may not call
//     roscpp (it takes locks and allocates), so the handler only wakes a thread kept waiting
//     for this (a write to a pipe, which is async-signal-safe) and waits up to 500 ms for it
//     to publish the zero Twists, then dies of the signal with the default action (core dump
//     as usual). When the fault left roscpp's own state broken (a lock held by the thread that
//     faulted, a corrupted heap), that thread may hang or fault in turn; the wait then ends
//     and the process dies without the zero Twist.
//   - from the moment it fires, every other cmd_vel publish of the node passes only a zero
//     Twist (command_gate.hpp), so the link's repeater cannot send a moving command after the
//     zero one.
// What it cannot cover: SIGKILL (the kernel's OOM killer, `kill -9`) and SIGSTOP cannot be
// caught; nor a power loss, a kernel panic or a lost network. The subscriber then sees no zero
// Twist: the last command it received stays the last, the publisher's TCP connection closes
// (after SIGKILL) or simply goes quiet, and the master still lists the node until it is
// cleaned up. Only the robot's own cmd_vel timeout stops it then: hw/ros/README.md asks for one.
// A thread stack overflow is caught only on the main thread (the only one given an alternate
// signal stack).
#include <string>

#include "ros/ros_session.hpp"

namespace oasis::hw::ros_node {

class LastResortStop {
 public:
  // Advertises `topic` (a publisher of the node's own; subscribers connect to it now, not when
  // it is needed) and installs the handlers. Throws RosError when `topic` is not a valid name.
  // One at a time in a process.
  LastResortStop(RosSession& session, const std::string& topic);
  // Disarms: the handlers of before come back. The node then ends on its ordinary path.
  ~LastResortStop();
  LastResortStop(const LastResortStop&) = delete;
  LastResortStop& operator=(const LastResortStop&) = delete;
};

}  // namespace oasis::hw::ros_node
