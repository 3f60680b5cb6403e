// oasis-ros: Online Attention Switching on any ROS 1 robot. The loop of `oasis-go1 run` -
// the catalog, the controller profile, perception, the attention filter, the policy and the
// step log - with ROS topics for its edges: images or a tracker's detections in, cmd_vel out,
// and the belief, the attended context and rviz markers published each step (README.md here).

#include <csignal>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/control_loop.hpp"
#include "app/profile_controller.hpp"
#include "app/session.hpp"
#include "go1/stop_signal.hpp"
#include "log/step_log_writer.hpp"
#include "log/table2_metrics.hpp"
#include "log/table2_report.hpp"
#include "perception/perception.hpp"
#include "perception/tag_visibility.hpp"
#include "ros/attention_publisher.hpp"
#include "ros/cmd_vel_link.hpp"
#include "ros/node_settings.hpp"
#include "ros/ros_session.hpp"
#include "ros/topic_inputs.hpp"

namespace oasis::hw::ros_node {
namespace {

struct NodeRequest {
  std::string log_path;
  std::optional<std::uint64_t> steps;
  int master_timeout_ms = 10000;
  bool quiet = false;
};

// The loop's frame source: the feed's next observation, kept for perception, the link's pose
// and the ground truth of the same instant. Ends on a stop signal or when ROS shuts down.
class FeedFrames final : public FrameSource {
 public:
  FeedFrames(InputFeed& feed, const RosSession& session) : feed_(feed), session_(session) {}

  NextFrame next() override {
    while (true) {
      if (go1::stop_signal_received()) return SourceStop{SourceStop::Kind::kEnd, "stop signal"};
      if (!session_.ok()) return SourceStop{SourceStop::Kind::kEnd, "ROS shut down"};
      std::optional<ObservedInput> input = feed_.next(std::chrono::milliseconds(50));
      if (!input) continue;
      current_ = std::move(input);
      Frame frame = current_->frame ? *current_->frame : Frame{};
      frame.timestamp_s = current_->stamp_s;
      return frame;
    }
  }

  const std::optional<ObservedInput>& current() const { return current_; }

 private:
  InputFeed& feed_;
  const RosSession& session_;
  std::optional<ObservedInput> current_;
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

std::vector<std::string> catalog_context_names(const rt::CatalogView& catalog) {
  std::vector<std::string> names;
  for (std::uint32_t k = 0; k < catalog.num_abstractions; ++k)
    names.emplace_back(catalog.abstractions[k].context);
  return names;
}

// "parameter ~loop/rate_hz: expected ...": a settings key as the ROS parameter it is.
void print_parameter_errors(const settings::SettingsError& error, const RosSession& session) {
  for (const settings::Diagnostic& diagnostic : error.diagnostics()) {
    std::string parameter = diagnostic.key;
    for (char& c : parameter)
      if (c == '.') c = '/';
    std::cerr << "oasis-ros: error: parameter ~" << parameter << " (" << session.node_name()
              << "/" << parameter << "): " << diagnostic.message << '\n';
  }
}

void print_step(const log::StepRecord& record) {
  std::printf("%7.1f s  step %-5llu %-20s %-15s reward %.0f  holder %d\n", record.time_s,
              static_cast<unsigned long long>(record.step), record.abstraction_name.c_str(),
              record.action_name.c_str(), record.reward, record.holder);
}

int run_node(const NodeRequest& request, int argc, char** argv) {
  go1::install_stop_signal_handlers();
  RosSession session(argc, argv, "oasis_ros",
                     std::chrono::milliseconds(request.master_timeout_ms));
  const std::string cmd_vel_fallback = session.private_string_parameter("ros/topics/cmd_vel",
                                                                       RosTopics{}.cmd_vel);
  auto stop_before_start = [&] {
    CmdVelLink::send_zero_once(session, cmd_vel_fallback, std::chrono::milliseconds(2000));
    session.shut_down(std::chrono::milliseconds(200));
    return 1;
  };

  NodeSettings settings;
  std::optional<app::SessionCatalog> catalog;
  settings::ControllerProfile profile;
  std::unique_ptr<app::LoopController> controller;
  try {
    settings = parse_node_settings(session.private_parameters_yaml(),
                                   "the ROS parameters of " + session.node_name());
    catalog.emplace(settings.go1.loop.catalog, settings.go1.loop.catalog_spec);
    profile = app::robot_profile(settings.go1.loop.controller);
    controller = app::make_controller(
        profile, {catalog->view(), app::controller_settings(settings.go1, catalog->view()), {}});
  } catch (const settings::SettingsError& e) {
    print_parameter_errors(e, session);
    return stop_before_start();
  } catch (const std::exception& e) {
    std::cerr << "oasis-ros: error: " << e.what() << '\n';
    return stop_before_start();
  }

  TopicInputs inputs(session, {settings.ros.mode, settings.ros.topics, settings.ros.use_odom,
                               catalog_context_names(catalog->view())});
  FeedFrames frames(inputs, session);
  const double period_s = 1.0 / settings.go1.loop.rate_hz;
  CmdVelLink link(session,
                  {settings.ros.topics.cmd_vel, period_s, settings.go1.loop.keepalive,
                   settings.ros.input_timeout},
                  [&frames]() -> std::optional<go1::Pose> {
                    return frames.current() ? frames.current()->odometry : std::nullopt;
                  });
  ObservedPerception perception(frames, settings.go1);
  AttentionPublisher topics(session, catalog->view(), settings.go1.perception.reach,
                         settings.ros.base_frame);
  std::optional<log::StepLogWriter> log_writer;
  if (!request.log_path.empty()) log_writer.emplace(request.log_path);

  std::vector<log::StepRecord> records;
  app::LoopParts parts{frames,
                       perception,
                       *controller,
                       link,
                       [&frames]() -> std::optional<log::GroundTruth> {
                         return frames.current() ? frames.current()->truth : std::nullopt;
                       },
                       [&](const log::StepRecord& record) {
                         if (log_writer) log_writer->write(record);
                         if (!request.quiet) print_step(record);
                         topics.publish(record, frames.current() ? frames.current()->stamp_s : 0);
                         records.push_back(record);
                       },
                       [] { return go1::stop_signal_received(); }};
  app::LoopOptions options;
  options.period_s = period_s;
  options.keepalive_s = std::chrono::duration<double>(settings.go1.loop.keepalive).count();
  options.realtime = false;  // the input's pace is the loop's; the link repeats between steps
  options.max_steps = request.steps;
  std::cerr << "oasis-ros: " << catalog->describe() << "; controller " << profile.name << " ("
            << settings::profile_summary(profile) << "); " << inputs.describe() << "; "
            << link.describe() << '\n';

  app::LoopResult result;
  try {
    result = app::run_loop(parts, options);
  } catch (const std::exception& e) {
    link.shut_down();
    std::cerr << "oasis-ros: error: " << e.what() << "; the robot was sent a zero Twist\n";
    session.shut_down(std::chrono::milliseconds(200));
    return 1;
  }
  link.shut_down();
  std::cerr << "oasis-ros: " << result.steps << " steps"
            << (result.reason.empty() ? "" : ", ended by " + result.reason)
            << "; a zero Twist was sent; fail-safe stops " << link.fail_safe_stops()
            << ", inputs dropped " << inputs.dropped() << ", refused " << inputs.refused()
            << (inputs.refused() > 0 ? " (last: " + inputs.last_refusal() + ")" : "") << '\n';
  session.shut_down(std::chrono::milliseconds(200));
  if (!request.quiet && !records.empty() && records.front().truth)
    log::print_table2(std::cout, log::summarize_trials({log::score_trial(records)}));
  if (go1::received_stop_signal() != 0) {
    std::cout.flush();
    go1::restore_default_signal_handlers();
    std::raise(go1::received_stop_signal());
  }
  return 0;
}

// The arguments that are ROS remappings (name:=value, __name:=...), which ros::init takes.
bool is_remapping(const std::string& argument) {
  return argument.find(":=") != std::string::npos;
}

}  // namespace
}  // namespace oasis::hw::ros_node

int main(int argc, char** argv) {
  using namespace oasis::hw::ros_node;
  CLI::App app{
      "oasis-ros: Online Attention Switching on a ROS 1 robot - images (or your tracker's "
      "detections) in, cmd_vel out, the belief and rviz markers published",
      "oasis-ros"};
  NodeRequest request;
  app.add_option("--log", request.log_path,
                 "write every step as a JSON line (hw/log/README.md) to this file");
  app.add_option("--steps", request.steps, "stop after this many control steps");
  app.add_option("--master-timeout-ms", request.master_timeout_ms,
                 "how long to wait for the ROS master before giving up")
      ->check(CLI::Range(100, 600000));
  app.add_flag("--quiet", request.quiet, "no line per step, no score table");
  app.footer(
      "Settings are the node's private ROS parameters, with the names and checks of "
      "hw/config/go1.yaml plus a ros: section (mode, topics, input_timeout_ms, use_odom, "
      "frames): e.g. _ros/mode:=detections, or a rosparam file in hw/ros/launch/oasis.launch. "
      "Topic names are relative and remap as usual (cmd_vel:=/robot/cmd_vel). A zero Twist is "
      "sent when no fresh input comes, on Ctrl-C or SIGTERM, and on any error. hw/ros/README.md "
      "has a robot owner's step-by-step.");
  std::vector<std::string> ours;
  for (int k = argc - 1; k >= 1; --k)
    if (!is_remapping(argv[k])) ours.emplace_back(argv[k]);
  try {
    app.parse(ours);
  } catch (const CLI::ParseError& e) {
    const int status = app.exit(e);
    return status == 0 ? 0 : 2;
  }
  try {
    return run_node(request, argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "oasis-ros: error: " << e.what() << '\n';
    return 1;
  }
}
