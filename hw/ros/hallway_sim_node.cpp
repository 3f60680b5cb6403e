// oasis-ros-hallway-sim: the hallway scenario of `oasis-go1 sim` (hw/sim) as a ROS 1 node, so
// that oasis-ros can be tested in a closed loop over topics. Each period the robot advances by
// the cmd_vel latest at the frame before, held over one period (go1::advanced, as the dry
// run of `oasis-go1 sim` moves it), the world by one
// frame on the rendered path, and the frame goes out as odom, ground_truth and the camera's
// topics, with one stamp (hallway_sim_topics.hpp, the node's ROS side; this file is C++20 and
// ROS-free, as hw/ros/CMakeLists.txt explains).

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <variant>
#include <vector>

#include <CLI/CLI.hpp>

#include "command_line/empty_values.hpp"
#include "command_line/number_options.hpp"
#include "go1/planar_pose.hpp"
#include "go1/stop_signal.hpp"
#include "perception/treat_holder.hpp"
#include "process/ending_signals.hpp"
#include "ros/hallway_sim_topics.hpp"
#include "ros/print_error.hpp"
#include "ros/ros_session.hpp"
#include "settings/settings.hpp"
#include "settings/settings_error.hpp"
#include "sim/hallway_world.hpp"
#include "sim/scenario.hpp"

namespace oasis::hw::ros_node {
namespace {

using Clock = std::chrono::steady_clock;

constexpr const char* kProgram = "oasis-ros-hallway-sim";
constexpr std::uint64_t kProgressEvery = 25;  // frames per progress line
constexpr std::chrono::seconds kSubscriberWait{30};
constexpr std::chrono::milliseconds kFlush{200};  // after the last frame, before leaving ROS
// `oasis-go1 sim --seed S` runs its trial k (0-based; its files say trialNN, NN = k + 1) on the
// seed S * 1000 + k (sim_command.cpp, trial_seed()).
constexpr std::uint64_t kTrialsPerSimSeed = 1000;

struct SimNodeRequest {
  std::string scenario;  // empty: the built-in defaults (hw/config/hallway.yaml)
  std::string config;    // empty: the built-in defaults (hw/config/go1.yaml)
  std::uint64_t seed = 1 * kTrialsPerSimSeed;  // oasis-go1 sim --seed 1, trial 01
  std::optional<std::uint64_t> steps;          // nothing: the whole trial
  std::optional<double> rate_hz;               // nothing: the settings' loop.rate_hz
  std::uint64_t wait_for_subscribers = 1;
  std::string bag;  // empty: no bag
  int master_timeout_ms = 10000;
};

// What `oasis-go1 sim` gives its world (sim_trial.cpp, world_options()), on the rendered path.
sim::HallwayWorldOptions world_options(const sim::HallwayScenario& scenario,
                                       const settings::Go1Settings& settings, std::uint64_t seed) {
  sim::HallwayWorldOptions options;
  options.scenario = scenario;
  options.seed = seed;
  options.period_s = 1.0 / settings.loop.rate_hz;
  options.camera.intrinsics = settings.camera.intrinsics;
  options.camera.mount = settings.perception.mount;
  options.camera.reach = settings.perception.reach;
  options.render.intrinsics = settings.camera.intrinsics;
  options.render.mount = settings.perception.mount;
  // A ROS depth image is 16UC1 in millimetres (REP-118), whatever the camera's own unit.
  options.render.depth_scale_m_per_unit = 0.001;
  options.path = sim::ObservationPath::kRendered;
  return options;
}

// The catalog's name of the true context, as loop/treat_contexts.cpp spells the Go1 spec's
// (that file looks the names up in a catalog, which this node has none of). As in
// sim_trial.cpp, anyone but human 1 holding is human 2's context.
std::string context_name(TreatHolder holder) {
  return holder == TreatHolder::kHuman1 ? "human1_holds_treat" : "human2_holds_treat";
}

int holder_number(TreatHolder holder) {
  return holder == TreatHolder::kHuman1 ? 1 : 2;
}

// ---- the run ----

enum class RunEnd { kTrialOver, kStepLimit, kSignal, kRosShutdown };

std::string to_string(RunEnd end) {
  switch (end) {
    case RunEnd::kTrialOver:
      return "the trial is over";
    case RunEnd::kStepLimit:
      return "--steps reached";
    case RunEnd::kSignal:
      return process::ending_signal_name(go1::received_stop_signal());
    case RunEnd::kRosShutdown:
      return "ROS shut the node down";
  }
  return "?";
}

std::optional<RunEnd> stop_requested(const RosSession& session) {
  if (go1::stop_signal_received()) return RunEnd::kSignal;
  if (!session.ok()) return RunEnd::kRosShutdown;
  return std::nullopt;
}

// Waits (up to kSubscriberWait) until the colour topic has `wanted` subscribers. Nothing when
// they came or the wait ran out (said on stderr); the reason when asked to stop meanwhile.
std::optional<RunEnd> wait_for_subscribers(const RosSession& session,
                                           const HallwaySimTopics& topics, std::uint64_t wanted) {
  if (topics.colour_subscribers() >= wanted) return std::nullopt;
  std::cerr << kProgram << ": waiting for " << wanted << " subscriber(s) on "
            << topics.colour_topic() << '\n';
  const Clock::time_point deadline = Clock::now() + kSubscriberWait;
  while (topics.colour_subscribers() < wanted) {
    if (const std::optional<RunEnd> stop = stop_requested(session)) return stop;
    if (Clock::now() >= deadline) {
      std::cerr << kProgram << ": warning: " << topics.colour_subscribers() << " of " << wanted
                << " subscriber(s) on " << topics.colour_topic() << " after "
                << kSubscriberWait.count() << " s; starting anyway\n";
      return std::nullopt;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return std::nullopt;
}

// A fixed-rate tick on the wall clock, as ros::WallRate: sleep() returns false when the tick
// was already past, and then counts from now rather than bursting to catch up.
class WallTicks {
 public:
  explicit WallTicks(double rate_hz)
      : period_(std::chrono::duration_cast<Clock::duration>(
            std::chrono::duration<double>(1.0 / rate_hz))),
        next_(Clock::now() + period_) {}

  bool sleep() {
    const Clock::time_point now = Clock::now();
    if (now >= next_) {
      next_ = now + period_;
      return false;
    }
    std::this_thread::sleep_until(next_);
    next_ += period_;
    return true;
  }

 private:
  Clock::duration period_;
  Clock::time_point next_;
};

std::string describe_frame(std::uint64_t frames, std::uint64_t total, const sim::FrameTruth& t,
                           const go1::VelocityCommand& velocity) {
  char text[256];
  std::snprintf(text, sizeof text,
                "frame %llu/%llu (%.1f s): human %d holds the treat%s, true reward %d; robot at "
                "(%.2f, %.2f) m, yaw %.2f rad; cmd_vel (%.2f m/s, %.2f m/s, %.2f rad/s)",
                static_cast<unsigned long long>(frames), static_cast<unsigned long long>(total),
                t.time_s, holder_number(t.scene.holder), t.scene.treat_hidden ? " (hidden)" : "",
                t.holder_in_reach ? 1 : 0, t.robot.x, t.robot.y, t.robot.yaw, velocity.forward,
                velocity.lateral, velocity.yaw_rate);
  return text;
}

struct RunSummary {
  RunEnd end = RunEnd::kTrialOver;
  std::uint64_t frames = 0;
  std::uint64_t rewarded = 0;  // frames with the true reward 1
  std::uint64_t late_ticks = 0;
  std::optional<sim::FrameTruth> last;
};

// The frames, from the first to the end (of the trial, of --steps, or a stop). The robot's
// pose starts at the origin and, before each frame after the first, advances over one period by
// the cmd_vel that was latest when the frame before was published: the decision taken on frame
// k shows in frame k + 2, exactly as in `oasis-go1 sim`, whose dry-run link moves the robot
// when the next command comes (loop/robot_link.hpp). The closed loop over topics and that
// command then see the same motion, so their scores compare like with like.
RunSummary run_frames(const RosSession& session, HallwaySimTopics& topics, sim::HallwayWorld& world,
                      go1::Pose& robot, double period_s, double rate_hz, std::uint64_t total) {
  RunSummary summary;
  WallTicks ticks(rate_hz);
  go1::VelocityCommand in_force;  // latest at the previous frame
  while (true) {
    if (summary.frames >= total) {
      summary.end = summary.frames >= world.steps() ? RunEnd::kTrialOver : RunEnd::kStepLimit;
      return summary;
    }
    if (summary.frames > 0 && !ticks.sleep()) ++summary.late_ticks;
    if (const std::optional<RunEnd> stop = stop_requested(session)) {
      summary.end = *stop;
      return summary;
    }
    if (summary.frames > 0) robot = go1::advanced(robot, in_force, period_s);
    const go1::VelocityCommand velocity = in_force;
    in_force = topics.latest_command();
    NextFrame next = world.next();  // asks for `robot`
    if (const SourceStop* stop = std::get_if<SourceStop>(&next)) {
      if (stop->kind == SourceStop::Kind::kFailure)
        throw std::runtime_error("the hallway world failed: " + stop->reason);
      summary.end = RunEnd::kTrialOver;
      return summary;
    }
    const sim::FrameTruth& truth = *world.truth_of_last_frame();
    topics.publish(std::get<Frame>(next), truth.robot, velocity, context_name(truth.scene.holder),
                   truth.holder_in_reach ? 1.0 : 0.0);
    ++summary.frames;
    if (truth.holder_in_reach) ++summary.rewarded;
    summary.last = truth;
    if (summary.frames % kProgressEvery == 0)
      std::cerr << kProgram << ": " << describe_frame(summary.frames, total, truth, velocity)
                << '\n';
  }
}

void print_summary(const RunSummary& summary, std::uint64_t total, const HallwaySimTopics& topics,
                   const sim::TreatSchedule& schedule) {
  std::cerr << kProgram << ": " << summary.frames << "/" << total << " frame(s) published ("
            << to_string(summary.end) << "); true reward 1 in " << summary.rewarded
            << " of them; hand-offs decided at";
  if (schedule.hand_off_s.empty()) std::cerr << " none";
  for (std::size_t k = 0; k < schedule.hand_off_s.size(); ++k) {
    char text[32];
    std::snprintf(text, sizeof text, "%s%.1f s", k == 0 ? " " : ", ", schedule.hand_off_s[k]);
    std::cerr << text;
  }
  std::cerr << "; cmd_vel " << topics.commands_received() << " received, "
            << topics.commands_refused() << " refused; " << summary.late_ticks << " late tick(s)";
  if (summary.last) {
    char text[96];
    std::snprintf(text, sizeof text, "; robot last at (%.2f, %.2f) m, yaw %.2f rad",
                  summary.last->robot.x, summary.last->robot.y, summary.last->robot.yaw);
    std::cerr << text;
  }
  if (!topics.bag_path().empty())
    std::cerr << "; bag " << topics.bag_path() << " (" << topics.bag_messages() << " messages)";
  std::cerr << '\n';
}

int run(const SimNodeRequest& request, int argc, char** argv) {
  const sim::HallwayScenario scenario =
      request.scenario.empty() ? sim::HallwayScenario{} : sim::load_scenario(request.scenario);
  const settings::Go1Settings settings = request.config.empty()
                                             ? settings::default_settings()
                                             : settings::load_settings(request.config);
  const double rate_hz = request.rate_hz.value_or(settings.loop.rate_hz);
  const sim::HallwayWorldOptions options = world_options(scenario, settings, request.seed);

  go1::install_stop_signal_handlers();  // ROS's own SIGINT handler stays out (ros_session.hpp)
  RosSession session(argc, argv, "oasis_ros_hallway_sim",
                     std::chrono::milliseconds(request.master_timeout_ms));
  HallwaySimTopicOptions topic_options;
  topic_options.bag = request.bag;
  HallwaySimTopics topics(session, topic_options);
  go1::Pose robot;  // the odometry frame's origin, facing down the hallway
  sim::HallwayWorld world(options, [&robot] { return robot; });
  const std::uint64_t total = std::min(request.steps.value_or(world.steps()), world.steps());
  std::cerr << kProgram << ": trial seed " << request.seed << " (rendered), " << total
            << " frame(s) of " << options.period_s << " s at " << rate_hz << " Hz; human "
            << holder_number(world.schedule().first_holder)
            << " holds the treat first; cmd_vel from " << topics.cmd_vel_topic() << '\n';

  RunSummary summary;
  try {
    if (const std::optional<RunEnd> stop =
            wait_for_subscribers(session, topics, request.wait_for_subscribers))
      summary.end = *stop;
    else
      summary = run_frames(session, topics, world, robot, options.period_s, rate_hz, total);
  } catch (const std::exception&) {
    if (!topics.bag_path().empty())
      std::cerr << kProgram << ": the bag so far stays in " << topics.bag_path() << ".tmp\n";
    throw;
  }
  topics.close_bag();
  print_summary(summary, total, topics, world.schedule());
  // A signal or ROS's shutdown ends the run at once; otherwise the last frame gets time to
  // reach its subscribers. Either way the status is 0: the run ended as asked.
  const bool ended_normally =
      summary.end == RunEnd::kTrialOver || summary.end == RunEnd::kStepLimit;
  session.shut_down(ended_normally ? kFlush : std::chrono::milliseconds(0));
  return 0;
}

// ---- the command line ----

void add_options(CLI::App& app, SimNodeRequest& request) {
  app.add_option("--scenario", request.scenario,
                 "the hallway scenario, as oasis-go1 sim reads it (hw/config/hallway.yaml "
                 "documents every key; 'oasis-go1 sim --print-scenario' writes one); default: "
                 "the built-in defaults, which equal that file")
      ->check(CLI::ExistingFile);
  app.add_option("--config", request.config,
                 "oasis-go1 settings (hw/config/go1.yaml): the camera's intrinsics and mount, "
                 "the reach region (the true reward) and loop.rate_hz (the simulated period) "
                 "come from here; default: the built-in defaults, which equal that file")
      ->check(CLI::ExistingFile);
  app.add_option("--seed", request.seed,
                 "the trial's seed: its people, hand-offs, hiding and noise. 'oasis-go1 sim "
                 "--seed S' runs its trial NN (files CONTROLLER_trialNN) on the seed "
                 "S * 1000 + NN - 1: the default 1000 is trial 01 of --seed 1, 1011 its trial 12")
      ->capture_default_str()
      ->check(oasis::cli::whole_in(0, oasis::cli::max_of<std::uint64_t>()));
  app.add_option("--steps", request.steps,
                 "stop after this many frames; default: the whole trial (the scenario's "
                 "trial.duration_s over the period)")
      ->check(oasis::cli::whole_in(1, oasis::cli::max_of<std::uint64_t>()));
  app.add_option("--rate-hz", request.rate_hz,
                 "frames published per second of wall-clock time; default: the settings' "
                 "loop.rate_hz (5). A frame still moves the world and the robot by one period "
                 "of 1 / loop.rate_hz, so another rate only plays the same trial faster or "
                 "slower than real time")
      ->check(oasis::cli::real_in(oasis::cli::closed(0.01, 1000.0)));
  app.add_option("--wait-for-subscribers", request.wait_for_subscribers,
                 "before the first frame, wait until camera/color/image_raw has this many "
                 "subscribers, for up to 30 s (then start anyway); 0: start at once")
      ->capture_default_str()
      ->check(oasis::cli::whole_in(0, 1000));
  app.add_option(
      "--bag", request.bag,
      "also write every message published to this rosbag, under the topic names "
      "published (relative, without a leading slash); it is written to FILE.tmp and "
      "renamed to FILE when the run ends, on SIGINT, SIGTERM or SIGHUP too; after an error "
      "it stays FILE.tmp");
  app.add_option("--master-timeout-ms", request.master_timeout_ms,
                 "how long to wait for the ROS master before giving up")
      ->capture_default_str()
      ->check(oasis::cli::whole_in(100, 600000));
}

}  // namespace
}  // namespace oasis::hw::ros_node

namespace {

// The simulator node: its command line parsed, then run, every error reported. main()
// catches what escapes the set-up.
int run(int argc, char** argv) {
  using namespace oasis::hw::ros_node;
  CLI::App app{
      "oasis-ros-hallway-sim: the hallway scenario of 'oasis-go1 sim' (rendered path) as a ROS "
      "1 node, for oasis-ros in a closed loop. Each period the robot moves by the cmd_vel "
      "(geometry_msgs/Twist) that was latest at the frame before, as oasis-go1 sim moves it, the "
      "people by one "
      "period, and the frame goes out, with one stamp, on odom (nav_msgs/Odometry), "
      "ground_truth (diagnostic_msgs/DiagnosticArray: the true context and reward), "
      "camera/color/camera_info, camera/aligned_depth_to_color/image_raw (16UC1, mm) and "
      "camera/color/image_raw (bgr8). It stops after the trial, after --steps, or on SIGINT, "
      "SIGTERM or SIGHUP, with status 0.",
      kProgram};
  SimNodeRequest request;
  add_options(app, request);
  oasis::cli::refuse_empty_values(app);
  app.footer(
      "Topic names are relative to the node's namespace and remap as usual "
      "(cmd_vel:=/robot/cmd_vel). To face oasis-ros with the people of trial NN of "
      "'oasis-go1 sim --seed S', give --seed S*1000+NN-1 (the robot then follows oasis-ros, so "
      "what it sees differs from that run's).\n"
      "  oasis-ros-hallway-sim --seed 1000 --bag trial01.bag");
  try {
    app.parse(arguments_for_cli(argc, argv));
  } catch (const CLI::ParseError& e) {
    const int status = app.exit(e);
    return status == 0 ? 0 : 2;  // bad usage, distinct from 1 (an error in the input)
  }
  try {
    return run(request, argc, argv);
  } catch (const oasis::hw::settings::SettingsError& e) {
    std::cerr << e.what() << '\n';  // FILE:LINE:COL: error: KEY: MESSAGE, for each problem
  } catch (const std::exception& e) {
    print_error(kProgram, e.what());
  }
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (...) {
    // Only the set-up of the command line is left outside run()'s handlers: out of memory
    // before the node started. No allocation here.
    std::fputs("oasis-ros-hallway-sim: error: could not set up the command line\n", stderr);
    return 1;
  }
}
