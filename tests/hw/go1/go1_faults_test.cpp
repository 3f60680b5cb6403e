// Fault injection on the robot link (issue 15): the sender drives the fake Go1 through packet
// loss from 10% to 50%, duplication, delay spikes that reorder packets, and all of them at
// once; then the controller stalls (no fresh command). In every case the robot is halted
// within the watchdog's timeout plus the faults' own delays, moves no further than a stale
// packet can carry it, and ends standing.
//
// Timing as in go1_link_test.cpp (loopback_link.hpp).

#include <cmath>
#include <ostream>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "go1/fake_go1.hpp"
#include "go1/sender.hpp"
#include "loopback_link.hpp"

namespace oasis::hw::go1 {
namespace {

using namespace test;  // loopback_link.hpp: the timing and the loopback sender

constexpr milliseconds kTick{5};  // kStopHold is 20 ticks of stop: 0.5^20 ~ 1e-6 all lost at 50%

struct Fault {
  std::string name;
  FakeGo1Options options;
  milliseconds loss_allowance;  // consecutive lost halts tolerated (ticks * 5 ms)
};

// gtest prints the case by its name, not its bytes.
void PrintTo(const Fault& fault, std::ostream* out) {
  *out << fault.name;
}

FakeGo1Options faulty(double loss, double duplicate, double spike_probability, milliseconds spike) {
  FakeGo1Options options;
  options.loss_probability = loss;
  options.duplicate_probability = duplicate;
  options.spike_probability = spike_probability;
  options.spike = spike;
  options.delay = milliseconds(10);
  options.seed = 11;
  return options;
}

bool is_moving(const HighCommand& command) {
  return command.mode == Mode::kVelocityWalk &&
         (command.velocity[0] != 0.0f || command.velocity[1] != 0.0f || command.yaw_speed != 0.0f);
}

class Go1Faults : public testing::TestWithParam<Fault> {};

TEST_P(Go1Faults, TheRobotHaltsWhenTheControllerStallsAndEndsStanding) {
  const Fault& fault = GetParam();
  FakeGo1 robot(fault.options);
  SenderOptions options = loopback_options(robot.endpoint(), kStopHold, milliseconds(50));
  options.watchdog_timeout = kWatchdogTimeout;
  Clock::time_point last_fresh;
  {
    Sender sender(options);
    // 400 ms of fresh commands every 10 ms, then the controller stalls.
    const Clock::time_point end = Clock::now() + milliseconds(400);
    do {
      last_fresh = Clock::now();
      sender.set_command({0.4f, 0.0f, 0.0f});
      std::this_thread::sleep_for(milliseconds(10));
    } while (Clock::now() < end);
    std::this_thread::sleep_for(kWatchdogTimeout + kStopHold + fault.options.spike +
                                milliseconds(150));
    EXPECT_GT(robot.pose().x, 0.05) << "the robot never drove: the link did not work";
  }  // the sender shuts down: stop, then stand
  std::this_thread::sleep_for(fault.options.spike + milliseconds(50));

  const std::vector<AppliedCommand> applied = robot.applied_commands();
  ASSERT_FALSE(applied.empty());
  // The first halt after the last fresh command, on time.
  const AppliedCommand* halt = nullptr;
  for (const AppliedCommand& entry : applied)
    if (entry.at >= last_fresh && !is_moving(entry.command)) {
      halt = &entry;
      break;
    }
  ASSERT_NE(halt, nullptr) << fault.name << ": never halted";
  const milliseconds bound =
      kWatchdogTimeout + fault.options.delay + kSchedulingMargin + fault.loss_allowance;
  EXPECT_LE(std::chrono::duration_cast<milliseconds>(halt->at - last_fresh).count(), bound.count())
      << fault.name;
  // After it, only a stale (spiked) packet may move the robot, and never for longer than a
  // tick before the next halt takes effect.
  const AppliedCommand* moving_since = nullptr;
  for (const AppliedCommand& entry : applied) {
    if (entry.at <= halt->at) continue;
    if (is_moving(entry.command)) {
      if (moving_since == nullptr) moving_since = &entry;
      continue;
    }
    if (moving_since != nullptr) {
      EXPECT_LE(std::chrono::duration_cast<milliseconds>(entry.at - moving_since->at).count(),
                (2 * kTick + kSchedulingMargin).count())
          << fault.name << ": a stale command kept the robot moving";
      moving_since = nullptr;
    }
  }
  EXPECT_EQ(moving_since, nullptr) << fault.name << ": moving at the end";
  EXPECT_EQ(applied.back().command.mode, Mode::kIdle) << fault.name << ": not standing at the end";
  const FakeGo1Counts counts = robot.counts();
  if (fault.options.loss_probability > 0) {
    EXPECT_GT(counts.dropped, 0u);
  }
  if (fault.options.duplicate_probability > 0) {
    EXPECT_GT(counts.duplicated, 0u);
  }
  if (fault.options.spike_probability > 0) {
    EXPECT_GT(counts.spiked, 0u);
  }
  EXPECT_EQ(counts.refused, 0u);
}

// Allowances: consecutive lost halts at loss p, 0.2 ^ 8, 0.3 ^ 12 and 0.5 ^ 20 all ~ 1e-6.
INSTANTIATE_TEST_SUITE_P(
    Faults, Go1Faults,
    testing::Values(Fault{"loss10", faulty(0.1, 0, 0, milliseconds(0)), 6 * kTick},
                    Fault{"loss30", faulty(0.3, 0, 0, milliseconds(0)), 12 * kTick},
                    Fault{"loss50", faulty(0.5, 0, 0, milliseconds(0)), 20 * kTick},
                    Fault{"duplicates", faulty(0, 0.3, 0, milliseconds(0)), milliseconds(0)},
                    Fault{"spikes", faulty(0, 0, 0.05, milliseconds(120)), milliseconds(0)},
                    Fault{"everything", faulty(0.3, 0.2, 0.05, milliseconds(120)), 12 * kTick}),
    [](const testing::TestParamInfo<Fault>& param) { return param.param.name; });

}  // namespace
}  // namespace oasis::hw::go1
