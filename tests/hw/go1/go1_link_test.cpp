// The sender against the fake Go1 on loopback: driving, the watchdog, stop and the stop signal,
// packet loss and delay, and clear errors for bad addresses.
//
// Timing: the sender runs at 200 Hz (5 ms ticks) and the fake polls every 1 ms. "Stopped within
// the watchdog timeout" allows kSchedulingMargin on top, for a late tick on a loaded 2-core
// machine (also under ASan): a stop sent on time is late by at most one tick plus wake-up jitter.

#include <csignal>
#include <thread>

#include <gtest/gtest.h>

#include "go1/fake_go1.hpp"
#include "go1/high_cmd.hpp"
#include "go1/high_state.hpp"
#include "go1/link_error.hpp"
#include "go1/sender.hpp"
#include "go1/stop_signal.hpp"
#include "go1/udp_socket.hpp"
#include "loopback_link.hpp"

namespace oasis::hw::go1 {
namespace {

using namespace test;  // loopback_link.hpp: the timing and the loopback sender

SenderOptions options_for(const FakeGo1& robot) {
  SenderOptions options = loopback_options(robot.endpoint(), kStopHold, milliseconds(50));
  options.watchdog_timeout = kWatchdogTimeout;
  return options;
}

// Sets `command` every 10 ms for `duration`; returns the time just before the last set_command.
Clock::time_point drive_for(Sender& sender, const VelocityCommand& command, milliseconds duration) {
  const Clock::time_point end = Clock::now() + duration;
  Clock::time_point last_set;
  do {
    last_set = Clock::now();
    sender.set_command(command);
    std::this_thread::sleep_for(milliseconds(10));
  } while (Clock::now() < end);
  return last_set;
}

bool is_stop(const HighCommand& command) {
  return command.mode == Mode::kVelocityWalk && command.velocity[0] == 0.0f &&
         command.velocity[1] == 0.0f && command.yaw_speed == 0.0f;
}
bool is_stand(const HighCommand& command) {
  return command.mode == Mode::kIdle;
}
bool is_moving(const HighCommand& command) {
  return command.mode == Mode::kVelocityWalk && !is_stop(command);
}

// The first command applied at or after `since` that is not a motion command.
const AppliedCommand* first_halt_after(const std::vector<AppliedCommand>& applied,
                                       Clock::time_point since) {
  for (const AppliedCommand& entry : applied)
    if (entry.at >= since && !is_moving(entry.command)) return &entry;
  return nullptr;
}

// After `since`: no motion at all, stop before stand, and the last command is stand.
void expect_stop_then_stand(const std::vector<AppliedCommand>& applied, Clock::time_point since) {
  bool saw_stop = false, saw_stand = false;
  for (const AppliedCommand& entry : applied) {
    if (entry.at < since) continue;
    EXPECT_FALSE(is_moving(entry.command)) << "motion after the halt";
    if (is_stop(entry.command)) {
      EXPECT_FALSE(saw_stand) << "stop after stand";
      saw_stop = true;
    }
    saw_stand = saw_stand || is_stand(entry.command);
  }
  EXPECT_TRUE(saw_stop);
  EXPECT_TRUE(saw_stand);
  ASSERT_FALSE(applied.empty());
  EXPECT_TRUE(is_stand(applied.back().command));
}

long long ms_between(Clock::time_point from, Clock::time_point to) {
  return std::chrono::duration_cast<milliseconds>(to - from).count();
}

TEST(Go1Link, SenderDrivesTheFakeRobotForward) {
  FakeGo1 robot;
  Sender sender(options_for(robot));
  drive_for(sender, VelocityCommand{0.4f, 0.0f, 0.0f}, milliseconds(500));
  const Pose pose = robot.pose();
  EXPECT_GT(pose.x, 0.05);  // ramp at 1 m/s^2 to 0.4 m/s in 0.4 s: about 0.12 m
  EXPECT_NEAR(pose.y, 0.0, 1e-6);
  EXPECT_NEAR(pose.yaw, 0.0, 1e-6);
  EXPECT_EQ(robot.counts().refused, 0u);

  const SenderStatus status = sender.status();
  EXPECT_EQ(status.phase, SenderPhase::kDriving);
  EXPECT_GT(status.states_received, 0u);
  EXPECT_EQ(status.states_refused, 0u);
  ASSERT_TRUE(status.latest_state.has_value());
  EXPECT_GT(status.latest_state->position[0], 0.0f);
  EXPECT_EQ(status.latest_state->mode, Mode::kVelocityWalk);
}

TEST(Go1Link, CommandsAreClampedAndRampedOnTheWire) {
  FakeGo1 robot;
  SenderOptions options = options_for(robot);
  options.limits.max_linear_acceleration = 5.0f;  // 0.025 m/s per tick: 0.5 m/s in 0.1 s
  Sender sender(options);
  drive_for(sender, VelocityCommand{5.0f, 0.0f, -9.0f}, milliseconds(300));
  const std::vector<AppliedCommand> applied = robot.applied_commands();
  float previous = 0.0f;
  float largest = 0.0f;
  for (const AppliedCommand& entry : applied) {
    const float forward = entry.command.velocity[0];
    EXPECT_LE(forward - previous, 5.0f / 200.0f + 1e-5f);
    EXPECT_GE(entry.command.yaw_speed, -1.0f);
    previous = forward;
    largest = std::max(largest, forward);
  }
  EXPECT_LE(largest, 0.5f);  // max_forward
  EXPECT_GT(largest, 0.5f - 1e-6f);
}

TEST(Go1Link, WatchdogStopsTheRobotWhenCommandsStall) {
  FakeGo1 robot;
  Sender sender(options_for(robot));
  const Clock::time_point before_last_set =
      drive_for(sender, {0.4f, 0.0f, 0.0f}, milliseconds(300));
  std::this_thread::sleep_for(kWatchdogTimeout + kStopHold + milliseconds(100));

  const std::vector<AppliedCommand> applied = robot.applied_commands();
  const AppliedCommand* halt = first_halt_after(applied, before_last_set);
  ASSERT_NE(halt, nullptr);
  EXPECT_TRUE(is_stop(halt->command));
  const long long after_ms = ms_between(before_last_set, halt->at);
  EXPECT_GE(after_ms, kWatchdogTimeout.count());
  EXPECT_LE(after_ms, (kWatchdogTimeout + kSchedulingMargin).count());
  expect_stop_then_stand(applied, halt->at);
  EXPECT_EQ(sender.status().phase, SenderPhase::kStanding);

  const double x = robot.pose().x;
  std::this_thread::sleep_for(milliseconds(50));
  EXPECT_EQ(robot.pose().x, x);
}

TEST(Go1Link, DrivingResumesAfterTheWatchdog) {
  FakeGo1 robot;
  Sender sender(options_for(robot));
  drive_for(sender, {0.3f, 0.0f, 0.0f}, milliseconds(100));
  std::this_thread::sleep_for(kWatchdogTimeout + milliseconds(30));
  const double halted_x = robot.pose().x;
  drive_for(sender, {0.3f, 0.0f, 0.0f}, milliseconds(200));
  EXPECT_GT(robot.pose().x, halted_x);
}

TEST(Go1Link, StoppingTheSenderSendsStopThenStand) {
  FakeGo1 robot;
  Sender sender(options_for(robot));
  drive_for(sender, {0.4f, 0.0f, 0.0f}, milliseconds(200));
  const Clock::time_point stop_called = Clock::now();
  sender.stop();
  EXPECT_EQ(sender.status().phase, SenderPhase::kFinished);
  std::this_thread::sleep_for(milliseconds(20));  // the fake applies what is in flight
  const std::vector<AppliedCommand> applied = robot.applied_commands();
  const AppliedCommand* halt = first_halt_after(applied, stop_called);
  ASSERT_NE(halt, nullptr);
  EXPECT_LE(ms_between(stop_called, halt->at), kSchedulingMargin.count());
  expect_stop_then_stand(applied, halt->at);
}

TEST(Go1Link, StopSignalMakesTheSenderStopThenStandAndFinish) {
  FakeGo1 robot;
  SenderOptions options = options_for(robot);
  options.obey_stop_signal = true;
  clear_stop_signal();
  install_stop_signal_handlers();
  Sender sender(options);
  drive_for(sender, {0.4f, 0.0f, 0.0f}, milliseconds(200));
  const Clock::time_point raised = Clock::now();
  std::raise(SIGTERM);
  EXPECT_TRUE(stop_signal_received());
  EXPECT_EQ(received_stop_signal(), SIGTERM);
  ASSERT_TRUE(sender.wait_until_finished(milliseconds(2000)));
  std::this_thread::sleep_for(milliseconds(20));
  const std::vector<AppliedCommand> applied = robot.applied_commands();
  const AppliedCommand* halt = first_halt_after(applied, raised);
  ASSERT_NE(halt, nullptr);
  EXPECT_LE(ms_between(raised, halt->at), kSchedulingMargin.count());
  expect_stop_then_stand(applied, halt->at);
  restore_default_signal_handlers();
  clear_stop_signal();
}

TEST(Go1Link, RobotStillStopsUnderLossAndDelay) {
  FakeGo1Options lossy;
  lossy.loss_probability = 0.2;
  lossy.delay = milliseconds(20);
  lossy.seed = 7;
  FakeGo1 robot(lossy);
  Sender sender(options_for(robot));
  const Clock::time_point before_last_set =
      drive_for(sender, {0.4f, 0.0f, 0.0f}, milliseconds(400));
  EXPECT_GT(robot.pose().x, 0.05);
  std::this_thread::sleep_for(kWatchdogTimeout + kStopHold + milliseconds(150));

  const std::vector<AppliedCommand> applied = robot.applied_commands();
  const AppliedCommand* halt = first_halt_after(applied, before_last_set);
  ASSERT_NE(halt, nullptr);
  // Beyond the plain case: the delay, and 8 ticks for consecutive lost stops (0.2^8 ~ 3e-6).
  const milliseconds loss_allowance{8 * 5};
  EXPECT_LE(ms_between(before_last_set, halt->at),
            (kWatchdogTimeout + lossy.delay + kSchedulingMargin + loss_allowance).count());
  expect_stop_then_stand(applied, halt->at);

  const FakeGo1Counts counts = robot.counts();
  const double lost = static_cast<double>(counts.dropped) / static_cast<double>(counts.received);
  EXPECT_GT(lost, 0.08);
  EXPECT_LT(lost, 0.35);
  EXPECT_EQ(counts.refused, 0u);
}

TEST(Go1Link, FakeRobotRefusesAndCountsBadPackets) {
  FakeGo1 robot;
  UdpSocket client(Endpoint{"127.0.0.1", 0});
  HighCmdBytes corrupted = encode_high_cmd(HighCommand{}, kLevelFlagHighLevel);
  corrupted[60] ^= 0x10;
  const std::vector<std::uint8_t> garbage{1, 2, 3};
  ASSERT_FALSE(client.send_to(garbage, to_sockaddr(robot.endpoint())));
  ASSERT_FALSE(client.send_to(corrupted, to_sockaddr(robot.endpoint())));
  const Clock::time_point deadline = Clock::now() + milliseconds(1000);
  while (robot.counts().received < 2 && Clock::now() < deadline)
    std::this_thread::sleep_for(milliseconds(1));
  EXPECT_EQ(robot.counts().refused, 2u);
  EXPECT_EQ(robot.counts().applied, 0u);
  EXPECT_NE(robot.last_refusal().find("bad crc"), std::string::npos) << robot.last_refusal();
}

TEST(Go1Link, InvalidAddressesGiveClearErrors) {
  SenderOptions bad_robot;
  bad_robot.robot = Endpoint{"999.1.1.1", 8082};
  bad_robot.local = Endpoint{"127.0.0.1", 0};
  try {
    Sender sender(bad_robot);
    FAIL() << "no error for 999.1.1.1";
  } catch (const LinkError& error) {
    EXPECT_NE(std::string(error.what()).find("'999.1.1.1' is not an IPv4 address"),
              std::string::npos)
        << error.what();
  }

  SenderOptions foreign_local;
  foreign_local.local = Endpoint{"203.0.113.7", 0};  // TEST-NET-3: not an address of this host
  try {
    Sender sender(foreign_local);
    FAIL() << "no error binding to 203.0.113.7";
  } catch (const LinkError& error) {
    EXPECT_NE(std::string(error.what()).find("cannot bind UDP socket to 203.0.113.7:0"),
              std::string::npos)
        << error.what();
  }

  EXPECT_THROW(parse_endpoint("192.168.123.161"), LinkError);
  EXPECT_THROW(parse_endpoint("192.168.123.161:99999"), LinkError);
  EXPECT_THROW(parse_endpoint("robot.local:8082"), LinkError);
  EXPECT_EQ(parse_endpoint("192.168.123.161:8082"), (Endpoint{"192.168.123.161", 8082}));

  SenderOptions bad_rate;
  bad_rate.local = Endpoint{"127.0.0.1", 0};
  bad_rate.rate_hz = 0.0;
  EXPECT_THROW(Sender{bad_rate}, std::invalid_argument);
}

TEST(Go1Link, UnreachableRobotIsReportedNotFatal) {
  // A loopback-bound socket cannot reach the real robot's network: every send fails, and the
  // sender keeps running and says why.
  const Endpoint real_robot = SenderOptions{}.robot;  // the default: the Go1's own address
  Sender sender(loopback_options(real_robot, milliseconds(20), milliseconds(20)));
  sender.set_command({0.2f, 0.0f, 0.0f});
  std::this_thread::sleep_for(milliseconds(50));
  const SenderStatus status = sender.status();
  EXPECT_GT(status.send_failures, 0u);
  EXPECT_NE(status.last_send_error.find("sendto 192.168.123.161:8082"), std::string::npos)
      << status.last_send_error;
  EXPECT_EQ(status.states_received, 0u);
  sender.stop();
  EXPECT_EQ(sender.status().phase, SenderPhase::kFinished);
}

TEST(Go1Link, SilentRobotLeavesNoStateAndStopsCleanly) {
  Endpoint nobody;
  {
    UdpSocket placeholder(Endpoint{"127.0.0.1", 0});
    nobody = placeholder.local_endpoint();
  }  // closed: nothing listens there now
  Sender sender(loopback_options(nobody, milliseconds(20), milliseconds(20)));
  sender.set_command({0.2f, 0.0f, 0.0f});
  std::this_thread::sleep_for(milliseconds(50));
  const SenderStatus status = sender.status();
  EXPECT_GT(status.packets_sent, 0u);
  EXPECT_FALSE(status.latest_state.has_value());
}

// Issue 27: state is taken only from the robot's own address and port. A well-formed HighState
// from a second socket (another port on the same host) is ignored and counted, never decoded;
// the robot's own packets are still taken.
TEST(Go1Link, StateFromAnyoneButTheRobotIsIgnoredAndCounted) {
  UdpSocket robot(Endpoint{"127.0.0.1", 0});
  UdpSocket stranger(Endpoint{"127.0.0.1", 0});
  Sender sender(loopback_options(robot.local_endpoint(), milliseconds(20), milliseconds(20)));
  const sockaddr_in sender_address = to_sockaddr(sender.local_endpoint());

  HighState forged;
  forged.position = {9.0f, 9.0f, 0.0f};
  const HighStateBytes forged_bytes = encode_high_state(forged, kLevelFlagHighLevel);
  for (int i = 0; i < 12; ++i)
    ASSERT_FALSE(stranger.send_to(forged_bytes, sender_address).has_value());
  const Clock::time_point deadline = Clock::now() + milliseconds(1000);
  while (sender.status().datagrams_ignored < 12 && Clock::now() < deadline)
    std::this_thread::sleep_for(milliseconds(5));
  SenderStatus status = sender.status();
  EXPECT_EQ(status.datagrams_ignored, 12u);
  ASSERT_TRUE(status.last_ignored_from.has_value());
  EXPECT_EQ(*status.last_ignored_from, stranger.local_endpoint());
  EXPECT_EQ(status.states_received, 0u);
  EXPECT_EQ(status.states_refused, 0u);
  EXPECT_FALSE(status.latest_state.has_value());
  EXPECT_EQ(ignored_datagrams_text(status), "ignored 12 datagrams, the last from " +
                                                to_string(stranger.local_endpoint()) +
                                                " (not the robot)");

  HighState real;
  real.position = {1.0f, 2.0f, 0.0f};
  ASSERT_FALSE(robot.send_to(encode_high_state(real, kLevelFlagHighLevel), sender_address));
  while (sender.status().states_received == 0 && Clock::now() < deadline + milliseconds(1000))
    std::this_thread::sleep_for(milliseconds(5));
  status = sender.status();
  EXPECT_EQ(status.states_received, 1u);
  ASSERT_TRUE(status.latest_state.has_value());
  EXPECT_EQ(status.latest_state->position[0], 1.0f);
  EXPECT_EQ(status.latest_state->position[1], 2.0f);
  EXPECT_EQ(status.datagrams_ignored, 12u);
}

}  // namespace
}  // namespace oasis::hw::go1
