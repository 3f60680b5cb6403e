// The whole loop - synthetic camera, perception, filter, policy, link - in a dry run and
// against the fake Go1 on loopback: the robot goes to the treat holder, follows a hand-off,
// and stops within the watchdog's 200 ms when the loop stalls.
//
// Timing as in tests/hw/go1/go1_link_test.cpp: "within 200 ms" allows kSchedulingMargin on
// top, for a late tick on a loaded 2-core machine (also under ASan).
#include "loop/control_loop.hpp"

#include <chrono>
#include <cmath>
#include <condition_variable>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "go1/fake_go1.hpp"
#include "go1_treat_catalog.hpp"
#include "loop/go1_link.hpp"
#include "loop/synthetic_world.hpp"
#include "spec_controller_settings.hpp"

namespace oasis::hw::loop {
namespace {

using std::chrono::milliseconds;
constexpr milliseconds kWatchdogTimeout{200};
constexpr milliseconds kSchedulingMargin{50};

std::uint32_t abstraction_of(TreatHolder holder) {
  return holder == TreatHolder::kHuman1 ? 0u : 1u;  // the spec's context order
}

std::function<std::optional<log::GroundTruth>()> truth_of(const SyntheticWorld& world) {
  return [&world]() -> std::optional<log::GroundTruth> {
    const std::optional<WorldTruth>& truth = world.truth_of_last_frame();
    if (!truth) return std::nullopt;
    return log::GroundTruth{abstraction_of(truth->holder), truth->holder_in_reach ? 1.0 : 0.0};
  };
}

TEST(ControlLoop, DryRunReachesTheHolderAndFollowsTheHandOff) {
  const rt::CatalogView& catalog = go1_treat::catalog();
  ASSERT_STREQ(catalog.abstractions[0].context, "human1_holds_treat");
  DryRunLink link;
  SyntheticWorldSettings world_settings;
  world_settings.hand_offs = {{20.0, TreatHolder::kHuman2}};
  SyntheticWorld world(world_settings, [&link] { return link.pose(); });
  Perception perception;
  AttentionController controller(catalog, spec_settings(catalog));
  std::vector<log::StepRecord> records;
  LoopParts parts{world,
                  perception,
                  controller,
                  link,
                  truth_of(world),
                  [&records](const log::StepRecord& record) { records.push_back(record); },
                  {}};

  const LoopResult result = run_loop(parts, {.realtime = false, .max_steps = 200});
  EXPECT_EQ(result.end, LoopEnd::kStepLimit);
  ASSERT_EQ(records.size(), 200u);
  EXPECT_DOUBLE_EQ(records[10].time_s, 2.0);

  // Within 20 s the robot has the first holder in reach, and again the second after the
  // hand-off: the reward the loop observed says so, and so does the truth.
  auto rewarded = [&records](std::size_t from, std::size_t to, std::uint32_t holder) {
    for (std::size_t k = from; k < to; ++k)
      if (records[k].reward == 1.0 && records[k].truth->reward == 1.0 &&
          records[k].truth->abstraction == holder)
        return true;
    return false;
  };
  EXPECT_TRUE(rewarded(0, 100, 0));
  EXPECT_TRUE(rewarded(100, 200, 1));
  // Once rewarded, the filter knows the context.
  EXPECT_EQ(records[99].abstraction, 0u);
  EXPECT_EQ(records[199].abstraction, 1u);
}

// A frame source that blocks when told to, as a stalled camera or a hung perception would.
class StallableSource final : public FrameSource {
 public:
  explicit StallableSource(FrameSource& inner) : inner_(inner) {}
  NextFrame next() override {
    std::unique_lock lock(mutex_);
    stalled_.wait(lock, [this] { return !stall_ || release_; });
    if (release_) return SourceStop{SourceStop::Kind::kEnd, "released"};
    return inner_.next();
  }
  void stall() {
    const std::lock_guard lock(mutex_);
    stall_ = true;
  }
  void release() {
    {
      const std::lock_guard lock(mutex_);
      release_ = true;
    }
    stalled_.notify_all();
  }

 private:
  FrameSource& inner_;
  std::mutex mutex_;
  std::condition_variable stalled_;
  bool stall_ = false;
  bool release_ = false;
};

go1::SenderOptions loopback_sender(const go1::Endpoint& robot) {
  go1::SenderOptions options;
  options.robot = robot;
  options.local = {"127.0.0.1", 0};
  options.rate_hz = 200.0;
  options.watchdog_timeout = kWatchdogTimeout;
  options.obey_stop_signal = false;
  return options;
}

bool still(const go1::HighCommand& command) {
  return command.mode != go1::Mode::kVelocityWalk ||
         (command.velocity[0] == 0.0f && command.velocity[1] == 0.0f && command.yaw_speed == 0.0f);
}

// When the robot was stopped for good: the first applied command from which on every command
// is a stop or a stand.
std::optional<go1::FakeGo1::Clock::time_point> stopped_for_good(
    const std::vector<go1::AppliedCommand>& applied) {
  std::optional<go1::FakeGo1::Clock::time_point> since;
  for (const go1::AppliedCommand& command : applied) {
    if (!still(command.command))
      since.reset();
    else if (!since)
      since = command.at;
  }
  return since;
}

// Timestamps the loop's fresh commands (decisions and keep-alives) on their way to the link.
class TimedLink final : public RobotLink {
 public:
  explicit TimedLink(Go1Link& inner) : inner_(inner) {}
  void command(const go1::VelocityCommand& velocity, double time_s) override {
    {
      const std::lock_guard lock(mutex_);
      last_command_ = std::chrono::steady_clock::now();
    }
    inner_.command(velocity, time_s);
  }
  go1::Pose pose() const override { return inner_.pose(); }
  void shut_down() override { inner_.shut_down(); }
  std::string describe() const override { return inner_.describe(); }
  std::chrono::steady_clock::time_point last_command() const {
    const std::lock_guard lock(mutex_);
    return last_command_;
  }

 private:
  Go1Link& inner_;
  mutable std::mutex mutex_;
  std::chrono::steady_clock::time_point last_command_;
};

TEST(ControlLoop, DrivesTheFakeGo1TowardTheHolderAndStopsWhenTheLoopStalls) {
  const rt::CatalogView& catalog = go1_treat::catalog();
  go1::FakeGo1 robot;
  Go1Link go1_link(loopback_sender(robot.endpoint()));
  ASSERT_TRUE(go1_link.wait_for_robot(milliseconds(1000))) << go1_link.silence_report();
  TimedLink link(go1_link);

  SyntheticWorld world({}, [&link] { return link.pose(); });
  StallableSource source(world);
  Perception perception;
  AttentionController controller(catalog, spec_settings(catalog));
  std::vector<log::StepRecord> records;
  std::mutex records_mutex;
  LoopParts parts{source,
                  perception,
                  controller,
                  link,
                  truth_of(world),
                  [&](const log::StepRecord& record) {
                    const std::lock_guard lock(records_mutex);
                    records.push_back(record);
                  },
                  {}};
  LoopResult result;
  std::thread loop([&] { result = run_loop(parts, LoopOptions{}); });

  // Four seconds of driving (20 decisions): human 1, who holds the treat, is 2.5 m ahead and
  // 0.7 m left at the start; the robot must have closed in on them.
  std::this_thread::sleep_for(milliseconds(4000));
  const double start_distance = std::hypot(2.5, 0.7);
  const go1::Pose pose = robot.pose();
  const double distance = std::hypot(2.5 - pose.x, 0.7 - pose.y);
  EXPECT_LT(distance, start_distance - 0.5) << "robot at " << pose.x << ", " << pose.y;

  // Stall the loop: no more frames, so no fresh commands. The fake must be stopped for good
  // within the watchdog timeout of the last fresh command, and then told to stand.
  source.stall();
  std::this_thread::sleep_for(milliseconds(1000));
  const std::vector<go1::AppliedCommand> applied = robot.applied_commands();
  const auto stopped_at = stopped_for_good(applied);
  ASSERT_TRUE(stopped_at.has_value()) << "the fake Go1 was never stopped";
  EXPECT_LE(std::chrono::duration_cast<milliseconds>(*stopped_at - link.last_command()).count(),
            (kWatchdogTimeout + kSchedulingMargin).count());
  EXPECT_EQ(applied.back().command.mode, go1::Mode::kIdle) << "stand after the stop";
  const go1::Pose stopped = robot.pose();
  std::this_thread::sleep_for(milliseconds(200));
  EXPECT_EQ(robot.pose().x, stopped.x);

  source.release();
  loop.join();
  EXPECT_EQ(result.end, LoopEnd::kSourceEnded);
  link.shut_down();
  const std::lock_guard lock(records_mutex);
  EXPECT_GE(records.size(), 15u);
}

// Perception that works for a while, then throws (a driver error, a bad frame).
class FailingPerception final : public PerceptionStage {
 public:
  explicit FailingPerception(int good_frames) : good_frames_(good_frames) {}
  PerceptionResult step(const Frame& frame) override {
    if (good_frames_-- <= 0) throw std::runtime_error("perception failed");
    return perception_.step(frame);
  }

 private:
  Perception perception_;
  int good_frames_;
};

// Fault injection (issue 15): perception throws mid-run. The loop does not swallow it, and the
// robot stops on the watchdog alone, before anyone calls shut_down().
TEST(ControlLoop, APerceptionExceptionEndsTheLoopAndTheWatchdogStopsTheRobot) {
  const rt::CatalogView& catalog = go1_treat::catalog();
  go1::FakeGo1 robot;
  Go1Link go1_link(loopback_sender(robot.endpoint()));
  ASSERT_TRUE(go1_link.wait_for_robot(milliseconds(1000))) << go1_link.silence_report();
  TimedLink link(go1_link);
  SyntheticWorld world({}, [&link] { return link.pose(); });
  FailingPerception perception(10);  // two seconds of driving
  AttentionController controller(catalog, spec_settings(catalog));
  LoopParts parts{world, perception, controller, link, truth_of(world), {}, {}};
  std::string error;
  try {
    run_loop(parts, LoopOptions{});
  } catch (const std::runtime_error& thrown) {
    error = thrown.what();
  }
  EXPECT_EQ(error, "perception failed");
  EXPECT_GT(std::hypot(robot.pose().x, robot.pose().y), 0.1) << "it drove before the failure";
  std::this_thread::sleep_for(kWatchdogTimeout + kSchedulingMargin + milliseconds(200));
  const std::vector<go1::AppliedCommand> applied = robot.applied_commands();
  const auto stopped_at = stopped_for_good(applied);
  ASSERT_TRUE(stopped_at.has_value()) << "the fake Go1 was never stopped";
  EXPECT_LE(std::chrono::duration_cast<milliseconds>(*stopped_at - link.last_command()).count(),
            (kWatchdogTimeout + kSchedulingMargin).count());
  link.shut_down();
  std::this_thread::sleep_for(milliseconds(100));
  EXPECT_EQ(robot.applied_commands().back().command.mode, go1::Mode::kIdle);
}

}  // namespace
}  // namespace oasis::hw::loop
