// oasis-ros: Online Attention Switching on any ROS 1 robot. The loop of `oasis-go1 run` -
// the catalog, the controller profile, perception, the attention filter, the policy and the
// step log - with ROS topics for its edges: images or a tracker's detections in, cmd_vel out,
// and the belief, the attended context and rviz markers published each step (README.md here).

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <functional>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "command_line/empty_values.hpp"
#include "command_line/memory_option.hpp"
#include "command_line/number_options.hpp"
#include "go1/stop_signal.hpp"
#include "log/step_log_writer.hpp"
#include "log/table2_metrics.hpp"
#include "log/table2_report.hpp"
#include "loop/control_loop.hpp"
#include "loop/profile_controller.hpp"
#include "loop/session.hpp"
#include "perception/out_of_memory.hpp"
#include "perception/perception.hpp"
#include "perception/tag_visibility.hpp"
#include "ros/attention_publisher.hpp"
#include "ros/bag_feed.hpp"
#include "ros/cmd_vel_link.hpp"
#include "ros/last_resort_stop.hpp"
#include "ros/node_settings.hpp"
#include "ros/print_error.hpp"
#include "ros/ros_session.hpp"
#include "ros/topic_inputs.hpp"

namespace oasis::hw::ros_node {
namespace {

struct NodeRequest {
  std::string bag_path;     // replay this bag instead of joining a ROS graph
  std::string params_path;  // with --bag: the parameters as a YAML file
  std::string log_path;
  std::optional<std::uint64_t> steps;
  int master_timeout_ms = 10000;
  bool quiet = false;
  std::uint64_t memory_budget = 0;  // bytes in force, 0: none (for the out-of-memory message)
};

constexpr const char* kProgram = "oasis-ros";

// ROS's own rule for a topic's name, for the settings to check before any name reaches ROS.
bool is_topic_name(const std::string& name) {
  return ros_name_problem(name).empty();
}

// An error that ends the node, in the words every program uses: out of memory as such (not
// OpenCV's text), anything else after "oasis-ros: error: ".
void report_error(const std::exception& error, const NodeRequest& request,
                  const std::string& after = "") {
  if (is_out_of_memory(error))
    cli::report_out_of_memory(kProgram, request.memory_budget);
  else
    print_error(kProgram, error.what() + after);
}

// Seconds since the epoch on the wall clock, as ROS stamps are (comparable on one machine).
double wall_clock_s() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

// The loop's frame source: the feed's next observation, kept for perception, the link's pose
// and the ground truth of the same instant. Ends on a stop signal or when ROS shuts down.
class FeedFrames final : public FrameSource {
 public:
  // `ros_ok`: false once ROS shut down (always true for a bag).
  FeedFrames(InputFeed& feed, std::function<bool()> ros_ok)
      : feed_(feed), ros_ok_(std::move(ros_ok)) {}

  NextFrame next() override {
    while (true) {
      if (go1::stop_signal_received()) return SourceStop{SourceStop::Kind::kEnd, "stop signal"};
      if (!ros_ok_()) return SourceStop{SourceStop::Kind::kEnd, "ROS shut down"};
      std::optional<ObservedInput> input = feed_.next(std::chrono::milliseconds(50));
      if (!input && feed_.ended()) return SourceStop{SourceStop::Kind::kEnd, "the bag ended"};
      if (!input) continue;
      current_ = std::move(input);
      received_s_ = wall_clock_s();
      Frame frame = current_->frame ? *current_->frame : Frame{};
      frame.timestamp_s = current_->stamp_s;
      return frame;
    }
  }

  const std::optional<ObservedInput>& current() const { return current_; }
  double received_s() const { return received_s_; }  // when the loop took current()

 private:
  InputFeed& feed_;
  std::function<bool()> ros_ok_;
  std::optional<ObservedInput> current_;
  double received_s_ = 0.0;
};

// Perception of the observation: ours on a camera frame; in detections mode the tracker's
// positions, with the tag's visibility worked out as perception would from the same positions.
class ObservedPerception final : public PerceptionStage {
 public:
  ObservedPerception(const FeedFrames& frames, const settings::Go1Settings& settings)
      : frames_(frames), settings_(settings), camera_(settings.perception) {}

  PerceptionResult step(const Frame& frame) override {
    const std::optional<ObservedInput>& input = frames_.current();
    if (!input || !input->detections) return camera_.step(frame);
    PerceptionResult seen = *input->detections;
    const PerceptionConfig& config = settings_.perception;
    const CarriedTag carried{config.tag_black_edge_m, config.tag_height_m,
                             config.tag_edge_margin_px, config.tag_range_m};
    mark_tag_visibility(seen.humans, settings_.camera.intrinsics, config.mount, carried);
    return seen;
  }

 private:
  const FeedFrames& frames_;
  const settings::Go1Settings& settings_;
  Perception camera_;
};

// "parameter ~loop/rate_hz: expected ...": a settings key as the ROS parameter it is.
void print_parameter_errors(const settings::SettingsError& error, const RosSession& session) {
  for (const settings::Diagnostic& diagnostic : error.diagnostics()) {
    std::string parameter = diagnostic.key;
    for (char& c : parameter)
      if (c == '.') c = '/';
    print_error(kProgram, "parameter ~" + parameter + " (" + session.node_name() + "/" + parameter +
                              "): " + diagnostic.message);
  }
}

void print_step(const log::StepRecord& record) {
  std::printf("%7.1f s  step %-5llu %-20s %-15s reward %.0f  holder %d\n", record.time_s,
              static_cast<unsigned long long>(record.step), record.abstraction_name.c_str(),
              record.action_name.c_str(), record.reward, record.holder);
}

// What the loop runs, from the settings: the catalog, the profile and its controller. Throws
// settings::SettingsError or loop::SetupError.
struct Assembly {
  explicit Assembly(NodeSettings node_settings) : settings(std::move(node_settings)) {
    catalog.emplace(settings.go1.loop.catalog, settings.go1.loop.catalog_spec);
    profile = loop::robot_profile(settings.go1.loop.controller);
    controller = loop::make_controller(
        profile, {catalog->view(), loop::controller_settings(settings.go1, catalog->view()), {}});
  }

  TopicInputOptions input_options() const {
    std::vector<std::string> names;
    for (std::uint32_t k = 0; k < catalog->view().num_abstractions; ++k)
      names.emplace_back(catalog->view().abstractions[k].context);
    return {settings.ros.mode, settings.ros.topics, settings.ros.use_odom, names};
  }

  double period_s() const { return 1.0 / settings.go1.loop.rate_hz; }

  NodeSettings settings;
  std::optional<loop::SessionCatalog> catalog;
  settings::ControllerProfile profile;
  std::unique_ptr<loop::LoopController> controller;
};

// The loop over the feed's observations: perception (or the detections), the controller, the
// link; every step logged, printed and handed to `publish`.
struct Drive {
  loop::LoopResult result;
  std::vector<log::StepRecord> records;
  // Per step, in milliseconds of the wall clock: from the observation's stamp to the moment the
  // loop took it (the transport: serialising, sending, matching by stamp) and to the moment its
  // decision went to the link (all of it: also perception, the filter and the policy).
  std::vector<double> received_ms;
  std::vector<double> latencies_ms;
};

// "median 8.1 ms, p99 12.0 ms, max 14.2 ms over 300 steps"
std::string latency_summary(std::vector<double> latencies_ms) {
  if (latencies_ms.empty()) return "no steps";
  std::sort(latencies_ms.begin(), latencies_ms.end());
  auto quantile = [&](double q) {
    const auto index = static_cast<std::size_t>(q * static_cast<double>(latencies_ms.size() - 1));
    return latencies_ms[index];
  };
  char text[160];
  std::snprintf(text, sizeof text, "median %.1f ms, p99 %.1f ms, max %.1f ms over %zu steps",
                quantile(0.5), quantile(0.99), latencies_ms.back(), latencies_ms.size());
  return text;
}

Drive drive(Assembly& assembly, FeedFrames& frames, loop::RobotLink& link,
            const NodeRequest& request,
            const std::function<void(const log::StepRecord&, double)>& publish) {
  ObservedPerception perception(frames, assembly.settings.go1);
  std::optional<log::StepLogWriter> log_writer;
  if (!request.log_path.empty()) log_writer.emplace(request.log_path);
  Drive drive;
  loop::LoopParts parts{frames,
                        perception,
                        *assembly.controller,
                        link,
                        [&frames]() -> std::optional<log::GroundTruth> {
                          return frames.current() ? frames.current()->truth : std::nullopt;
                        },
                        [&](const log::StepRecord& record) {
                          const double stamp_s = frames.current()->stamp_s;
                          drive.received_ms.push_back((frames.received_s() - stamp_s) * 1000.0);
                          drive.latencies_ms.push_back((wall_clock_s() - stamp_s) * 1000.0);
                          if (log_writer) log_writer->write(record);
                          if (!request.quiet) print_step(record);
                          if (publish) publish(record, frames.current()->stamp_s);
                          drive.records.push_back(record);
                        },
                        [] { return go1::stop_signal_received(); }};
  loop::LoopOptions options;
  options.period_s = assembly.period_s();
  options.keepalive_s = std::chrono::duration<double>(assembly.settings.go1.loop.keepalive).count();
  options.realtime = false;  // the input's pace is the loop's; the link repeats between steps
  options.max_steps = request.steps;
  drive.result = loop::run_loop(parts, options);
  return drive;
}

// The Table II row when the observations carried ground truth (a simulator, or its bag).
void print_score(const NodeRequest& request, const std::vector<log::StepRecord>& records) {
  if (!request.quiet && !records.empty() && records.front().truth)
    log::print_table2(std::cout, log::summarize_trials({log::score_trial(records)}));
}

// Dies of the signal that stopped the loop, as an interrupted program should, once the robot
// was told to stop.
void raise_received_signal() {
  if (go1::received_stop_signal() == 0) return;
  std::cout.flush();
  go1::restore_default_signal_handlers();
  std::raise(go1::received_stop_signal());
}

std::string description(const Assembly& assembly, const InputFeed& feed,
                        const loop::RobotLink& link) {
  return assembly.catalog->describe() + "; controller " + assembly.profile.name + " (" +
         settings::profile_summary(assembly.profile) + "); " + feed.describe() + "; " +
         link.describe();
}

// Nothing started: the robot is told to stand still all the same, on the cmd_vel parameter's
// topic (the default cmd_vel when it is not set). When that parameter is itself no ROS name,
// no topic is named and nothing can be published: said so, rather than guessing a topic.
void stop_before_start(RosSession& session) {
  const std::string cmd_vel =
      session.private_string_parameter("ros/topics/cmd_vel", RosTopics{}.cmd_vel);
  if (!is_topic_name(cmd_vel)) {
    std::cerr << kProgram
              << ": no zero Twist was published: ~ros/topics/cmd_vel names no valid topic\n";
    return;
  }
  CmdVelLink::send_zero_once(session, cmd_vel, std::chrono::milliseconds(2000));
}

int run_node(const NodeRequest& request, int argc, char** argv) {
  go1::install_stop_signal_handlers();
  RosSession session(argc, argv, "oasis_ros", std::chrono::milliseconds(request.master_timeout_ms));
  std::unique_ptr<Assembly> assembly;
  try {
    assembly = std::make_unique<Assembly>(
        parse_node_settings(session.private_parameters_yaml(),
                            "the ROS parameters of " + session.node_name(), is_topic_name));
  } catch (const std::exception& e) {
    if (const auto* bad = dynamic_cast<const settings::SettingsError*>(&e))
      print_parameter_errors(*bad, session);
    else
      report_error(e, request);
    stop_before_start(session);
    session.shut_down(std::chrono::milliseconds(200));
    return 1;
  }

  const NodeSettings& settings = assembly->settings;
  // From here on an exception nobody catches, or a fatal signal, still ends with a zero Twist
  // (last_resort_stop.hpp says what it covers and what it cannot).
  LastResortStop last_resort(session, settings.ros.topics.cmd_vel);
  TopicInputs inputs(session, assembly->input_options());
  FeedFrames frames(inputs, [&session] { return session.ok(); });
  CmdVelLink link(session,
                  {settings.ros.topics.cmd_vel, assembly->period_s(), settings.go1.loop.keepalive,
                   settings.ros.input_timeout},
                  [&frames]() -> std::optional<go1::Pose> {
                    return frames.current() ? frames.current()->odometry : std::nullopt;
                  });
  AttentionPublisher topics(session, assembly->catalog->view(), settings.go1.perception.reach,
                            settings.ros.base_frame);
  std::cerr << "oasis-ros: " << description(*assembly, inputs, link) << '\n';

  Drive result;
  try {
    result = drive(*assembly, frames, link, request,
                   [&topics](const log::StepRecord& record, double stamp_s) {
                     topics.publish(record, stamp_s);
                   });
  } catch (const std::exception& e) {
    link.shut_down();
    report_error(e, request, "; the robot was sent a zero Twist");
    session.shut_down(std::chrono::milliseconds(200));
    return 1;
  }
  link.shut_down();
  std::cerr << "oasis-ros: " << result.result.steps << " steps"
            << (result.result.reason.empty() ? "" : ", ended by " + result.result.reason)
            << "; a zero Twist was sent; fail-safe stops " << link.fail_safe_stops()
            << ", inputs dropped " << inputs.dropped() << ", refused " << inputs.refused()
            << (inputs.refused() > 0 ? " (last: " + inputs.last_refusal() + ")" : "") << '\n'
            << "oasis-ros: latency from the observation's stamp to cmd_vel: "
            << latency_summary(result.latencies_ms)
            << "; of which to the observation's arrival: " << latency_summary(result.received_ms)
            << '\n';
  session.shut_down(std::chrono::milliseconds(200));
  print_score(request, result.records);
  raise_received_signal();
  return 0;
}

// A replay's robot: nothing is sent; the pose is the bag's odometry of the observation, or,
// without one, the commands integrated as a dry run does.
class ReplayLink final : public loop::RobotLink {
 public:
  explicit ReplayLink(const FeedFrames& frames) : frames_(frames) {}
  void command(const go1::VelocityCommand& velocity, double time_s) override {
    dry_run_.command(velocity, time_s);
  }
  go1::Pose pose() const override {
    const std::optional<ObservedInput>& input = frames_.current();
    return input && input->odometry ? *input->odometry : dry_run_.pose();
  }
  void shut_down() override { dry_run_.shut_down(); }
  std::string describe() const override { return "replay (nothing sent)"; }

 private:
  const FeedFrames& frames_;
  loop::DryRunLink dry_run_;
};

int replay_bag(const NodeRequest& request) {
  go1::install_stop_signal_handlers();
  std::unique_ptr<Assembly> assembly;
  try {
    assembly = std::make_unique<Assembly>(
        request.params_path.empty() ? NodeSettings{}
                                    : load_node_settings(request.params_path, is_topic_name));
  } catch (const settings::SettingsError& e) {
    std::cerr << e.what() << '\n';
    return 1;
  }
  BagFeed bag(request.bag_path, assembly->input_options());
  FeedFrames frames(bag, [] { return true; });
  ReplayLink link(frames);
  std::cerr << "oasis-ros: " << description(*assembly, bag, link) << '\n';
  const Drive result = drive(*assembly, frames, link, request, {});
  std::cerr << "oasis-ros: " << result.result.steps << " steps replayed"
            << (result.result.reason.empty() ? "" : ", ended by " + result.result.reason)
            << (bag.refused() > 0 ? "; " + std::to_string(bag.refused()) +
                                        " messages refused (last: " + bag.last_refusal() + ")"
                                  : "")
            << '\n';
  print_score(request, result.records);
  raise_received_signal();
  return 0;
}

}  // namespace
}  // namespace oasis::hw::ros_node

// An exception that escapes ends in std::terminate, whose handler (last_resort_stop.hpp)
// publishes the zero Twist before the process ends: that is the designed last path.
int main(int argc, char** argv) {  // NOLINT(bugprone-exception-escape)
  using namespace oasis::hw::ros_node;
  CLI::App app{
      "oasis-ros: Online Attention Switching on a ROS 1 robot - images (or your tracker's "
      "detections) in, cmd_vel out, the belief and rviz markers published",
      "oasis-ros"};
  NodeRequest request;
  app.add_option("--bag", request.bag_path,
                 "replay a rosbag offline instead of joining a ROS graph (no master needed): "
                 "the same input topics are read from it, the step log written, the Table II "
                 "score printed when it carries ground truth")
      ->check(CLI::ExistingFile);
  app.add_option("--params", request.params_path,
                 "with --bag: the node's parameters as a YAML file (go1.yaml's keys and ros:); "
                 "default: the defaults")
      ->check(CLI::ExistingFile);
  app.add_option("--log", request.log_path,
                 "write every step as a JSON line (hw/log/README.md) to this file");
  app.add_option("--steps", request.steps, "stop after this many control steps")
      ->check(oasis::cli::whole_in(0, oasis::cli::max_of<std::uint64_t>()));
  app.add_option("--master-timeout-ms", request.master_timeout_ms,
                 "how long to wait for the ROS master before giving up")
      ->capture_default_str()
      ->check(oasis::cli::whole_in(100, 600000));
  app.add_flag("--quiet", request.quiet, "no line per step, no score table");
  std::string memory_budget = "auto";
  oasis::cli::add_memory_budget_option(app, memory_budget);
  oasis::cli::refuse_empty_values(app);
  app.footer(
      "Settings are the node's private ROS parameters, with the names and checks of "
      "hw/config/go1.yaml plus a ros: section (mode, topics, input_timeout_ms, use_odom, "
      "frames): e.g. _ros/mode:=detections, or a rosparam file in hw/ros/launch/oasis.launch. "
      "Topic names are relative and remap as usual (cmd_vel:=/robot/cmd_vel). A zero Twist is "
      "sent when no fresh input comes, on Ctrl-C, SIGTERM or SIGHUP, and on any error. "
      "hw/ros/README.md "
      "has a robot owner's step-by-step.");
  try {
    app.parse(arguments_for_cli(argc, argv));
  } catch (const CLI::ParseError& e) {
    const int status = app.exit(e);
    return status == 0 ? 0 : 2;  // bad usage, distinct from 1 (an error in the input)
  }
  if (!request.params_path.empty() && request.bag_path.empty()) {
    print_error(kProgram, "--params goes with --bag; a live node reads the ROS parameters");
    return 2;
  }
  const std::optional<std::uint64_t> budget =
      oasis::cli::apply_memory_budget_option(app, memory_budget, kProgram);
  if (!budget) return 2;
  request.memory_budget = *budget;
  try {
    return request.bag_path.empty() ? run_node(request, argc, argv) : replay_bag(request);
  } catch (const std::exception& e) {
    report_error(e, request);
    return 1;
  }
}
