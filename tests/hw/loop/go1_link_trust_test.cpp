// Issue 27 at the loop's edge: Go1Link::wait_for_robot() counts only the robot's own HighState
// as "the robot answers". A stranger on the network sending well-formed HighState packets does
// not start the loop, and the silence report and the step log's link record name it.
#include <atomic>
#include <chrono>
#include <thread>

#include <gtest/gtest.h>

#include "go1/high_state.hpp"
#include "go1/udp_socket.hpp"
#include "loop/go1_link.hpp"

namespace oasis::hw::loop {
namespace {

using std::chrono::milliseconds;

go1::SenderOptions loopback_sender(const go1::Endpoint& robot) {
  go1::SenderOptions options;
  options.robot = robot;
  options.local = {"127.0.0.1", 0};
  options.rate_hz = 200.0;
  options.stop_hold = milliseconds(20);
  options.shutdown_stand_hold = milliseconds(20);
  options.obey_stop_signal = false;
  return options;
}

// Sends a valid HighState to `to` every 5 ms until stopped.
class Stranger {
 public:
  explicit Stranger(const go1::Endpoint& to)
      : socket_(go1::Endpoint{"127.0.0.1", 0}), thread_([this, to] { run(to); }) {}
  ~Stranger() {
    quit_ = true;
    thread_.join();
  }
  go1::Endpoint endpoint() const { return socket_.local_endpoint(); }

 private:
  void run(const go1::Endpoint& to) {
    go1::HighState forged;
    forged.position = {5.0f, 5.0f, 0.0f};
    const go1::HighStateBytes bytes = go1::encode_high_state(forged, go1::kLevelFlagHighLevel);
    while (!quit_) {
      (void)socket_.send_to(bytes, go1::to_sockaddr(to));
      std::this_thread::sleep_for(milliseconds(5));
    }
  }
  go1::UdpSocket socket_;
  std::atomic<bool> quit_{false};
  std::thread thread_;
};

TEST(Go1LinkTrust, AStrangersStateIsNotTheRobotAnswering) {
  go1::UdpSocket robot(go1::Endpoint{"127.0.0.1", 0});  // a robot that is silent at first
  Go1Link link(loopback_sender(robot.local_endpoint()));
  const Stranger stranger(link.sender().local_endpoint());

  EXPECT_FALSE(link.wait_for_robot(milliseconds(300)));
  const std::string report = link.silence_report();
  EXPECT_NE(report.find("received no valid HighState"), std::string::npos) << report;
  EXPECT_NE(report.find("datagrams, the last from " + go1::to_string(stranger.endpoint()) +
                        " (not the robot)"),
            std::string::npos)
      << report;
  EXPECT_EQ(link.pose().x, 0.0) << "the stranger's odometry was taken";

  const std::optional<log::LinkRecord> record = link.link_record();
  ASSERT_TRUE(record.has_value());
  EXPECT_GT(record->datagrams_ignored, 0u);
  EXPECT_EQ(record->last_ignored_from, go1::to_string(stranger.endpoint()));
  EXPECT_EQ(record->states_received, 0u);

  // Now the robot answers a command: that is taken, the stranger still is not.
  const std::optional<go1::Datagram> command = robot.receive(milliseconds(500));
  ASSERT_TRUE(command.has_value());
  go1::HighState real;
  real.position = {0.5f, 0.0f, 0.0f};
  ASSERT_FALSE(robot.send_to(go1::encode_high_state(real, go1::kLevelFlagHighLevel),
                             go1::to_sockaddr(command->from)));
  EXPECT_TRUE(link.wait_for_robot(milliseconds(1000))) << link.silence_report();
  EXPECT_FLOAT_EQ(static_cast<float>(link.pose().x), 0.5f);
  link.shut_down();
}

}  // namespace
}  // namespace oasis::hw::loop
