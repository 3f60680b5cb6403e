// `oasis-go1 run` and `oasis-go1 replay`: assemble a session from the settings and the command
// line, run the loop, log every step, and always leave the robot standing.

#include <csignal>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "app/commands.hpp"
#include "command_line/number_options.hpp"
#include "go1/endpoint.hpp"
#include "go1/sender.hpp"
#include "go1/stop_signal.hpp"
#include "go1/watchdog.hpp"
#include "log/step_log_writer.hpp"
#include "log/table2_metrics.hpp"
#include "log/table2_report.hpp"
#include "loop/control_loop.hpp"
#include "loop/profile_controller.hpp"
#include "loop/session.hpp"
#include "settings/settings.hpp"

namespace oasis::hw::app {
namespace {

struct RunRequest {
  std::string config;  // empty: the built-in defaults (equal to hw/config/go1.yaml)
  std::string source;  // empty: the config's
  std::string catalog;
  std::string catalog_spec;
  std::string controller;  // empty: the config's loop.controller
  std::string robot;       // ADDRESS[:PORT]; empty: the config's
  std::string log_path;
  std::optional<std::uint64_t> steps;
  bool dry_run = false;
  bool fast = false;
  bool replay = false;
  int robot_timeout_ms = 1000;
  bool quiet = false;
};

settings::Go1Settings effective_settings(const RunRequest& request) {
  settings::Go1Settings result = loop::settings_or_defaults(request.config);
  if (!request.source.empty()) result.source = loop::source_option(request.source);
  if (!request.catalog.empty()) result.loop.catalog = request.catalog;
  if (!request.catalog_spec.empty()) result.loop.catalog_spec = request.catalog_spec;
  if (!request.controller.empty()) result.loop.controller = request.controller;
  if (!request.robot.empty()) {
    try {
      const bool has_port = request.robot.find(':') != std::string::npos;
      result.link.robot = go1::parse_endpoint(
          has_port ? request.robot : request.robot + ':' + std::to_string(result.link.robot.port));
    } catch (const std::exception& e) {
      throw loop::SetupError(std::string("--robot: ") + e.what());
    }
  }
  return result;
}

const char* end_text(loop::LoopEnd end) {
  switch (end) {
    case loop::LoopEnd::kStepLimit:
      return "step limit reached";
    case loop::LoopEnd::kSourceEnded:
      return "the frame source ended";
    case loop::LoopEnd::kSourceFailed:
      return "the frame source failed";
    case loop::LoopEnd::kStopRequested:
      return "stop signal";
  }
  return "?";
}

void print_step(const log::StepRecord& record) {
  std::printf("%7.1f s  step %-5llu %-20s %-15s reward %.0f  holder %d\n", record.time_s,
              static_cast<unsigned long long>(record.step), record.abstraction_name.c_str(),
              record.action_name.c_str(), record.reward, record.holder);
}

// "received 1500 HighState, refused 0, ignored 12 datagrams, the last from 192.168.12.40:5555
// (not the robot)": the link's counts, printed when the run ends.
std::string link_summary(const log::LinkRecord& counts) {
  std::string text = "received " + std::to_string(counts.states_received) + " HighState, refused " +
                     std::to_string(counts.states_refused);
  if (counts.datagrams_ignored > 0)
    text += ", " + go1::ignored_datagrams_text(counts.datagrams_ignored, counts.last_ignored_from);
  return text;
}

// The session's result as the log's Table II row, when the log has ground truth.
void print_score(const std::vector<log::StepRecord>& records) {
  if (records.empty() || !records.front().truth) return;
  const log::TrialScore score = log::score_trial(records);
  log::print_table2(std::cout, log::summarize_trials({score}));
}

int run_session(const RunRequest& request) {
  const settings::Go1Settings settings = effective_settings(request);
  const loop::SessionCatalog catalog(settings.loop.catalog, settings.loop.catalog_spec);
  const settings::ControllerProfile profile = loop::robot_profile(settings.loop.controller);
  const std::unique_ptr<loop::LoopController> controller = loop::make_controller(
      profile, {catalog.view(), loop::controller_settings(settings, catalog.view()), {}});

  go1::install_stop_signal_handlers();
  std::unique_ptr<loop::RobotLink> link =
      loop::open_link(settings, request.dry_run || request.replay,
                      std::chrono::milliseconds(request.robot_timeout_ms));
  loop::SessionSource source = loop::open_source(settings, catalog.view(), *link);
  std::optional<log::StepLogWriter> log_writer;
  if (!request.log_path.empty()) log_writer.emplace(request.log_path);

  Perception perception(settings.perception);
  std::vector<log::StepRecord> records;
  loop::LoopParts parts{*source.source,
                        perception,
                        *controller,
                        *link,
                        source.truth,
                        [&](const log::StepRecord& record) {
                          if (log_writer) log_writer->write(record);
                          if (!request.quiet) print_step(record);
                          records.push_back(record);
                        },
                        [] { return go1::stop_signal_received(); }};
  loop::LoopOptions options;
  options.period_s = 1.0 / settings.loop.rate_hz;
  options.keepalive_s = std::chrono::duration<double>(settings.loop.keepalive).count();
  options.realtime = source.realtime_only || !(request.fast || request.replay);
  options.max_steps = request.steps;
  std::cerr << "oasis-go1: " << catalog.describe() << "; controller " << profile.name << " ("
            << profile.origin << ": " << settings::profile_summary(profile) << "); "
            << source.description << "; " << link->describe()
            << (options.realtime ? "" : "; as fast as it computes") << '\n';

  loop::LoopResult result;
  try {
    result = loop::run_loop(parts, options);
  } catch (...) {
    link->shut_down();
    throw;
  }
  link->shut_down();
  if (const std::optional<log::LinkRecord> counts = link->link_record())
    std::cerr << "oasis-go1: link: " << link_summary(*counts) << '\n';
  std::cerr << "oasis-go1: " << result.steps << " steps, " << end_text(result.end)
            << (result.reason.empty() ? "" : ": " + result.reason)
            << (request.dry_run || request.replay ? "" : "; the robot was told to stop and stand")
            << '\n';
  if (!request.quiet) print_score(records);
  if (result.end == loop::LoopEnd::kStopRequested && go1::received_stop_signal() != 0) {
    // Die of the signal, as a program interrupted should, now that the robot stands.
    std::cout.flush();
    go1::restore_default_signal_handlers();
    std::raise(go1::received_stop_signal());
  }
  return result.end == loop::LoopEnd::kSourceFailed ? 1 : 0;
}

void add_common_options(CLI::App& command, RunRequest& request) {
  command
      .add_option("--config", request.config,
                  "YAML settings (hw/config/go1.yaml documents every key); default: the "
                  "built-in defaults, which equal that file")
      ->check(CLI::ExistingFile);
  command.add_option("--catalog", request.catalog,
                     "'linked' (the Go1 catalog compiled into this program) or a .bin catalog "
                     "written by oasisc compile; default: the config's loop.catalog");
  command.add_option("--catalog-spec", request.catalog_spec,
                     "the spec the catalog must have been compiled from, checked by its spec hash: "
                     "'linked' (the linked catalog's spec), a .oasis file, or 'any'; default: "
                     "the config's loop.catalog_spec");
  command.add_option("--controller", request.controller,
                     "the controller profile: " + settings::shipped_profile_names() +
                         " (hw/config/controllers/; oracle and no-attention are sim baselines), "
                         "or a path to a .yaml profile; default: the config's loop.controller");
  command.add_option("--steps", request.steps, "stop after this many control steps")
      ->check(oasis::cli::whole_in(0, oasis::cli::max_of<std::uint64_t>()));
  command.add_option("--log", request.log_path,
                     "write every step as a JSON line (hw/log/README.md) to this file");
  command.add_flag("--quiet", request.quiet, "no line per step, no score table");
}

}  // namespace

CommandRunner add_run_command(CLI::App& app) {
  auto request = std::make_shared<RunRequest>();
  CLI::App* command = app.add_subcommand(
      "run", "run the 5 Hz loop: frames -> perception -> attention filter -> policy -> robot");
  add_common_options(*command, *request);
  command->add_option("--source", request->source,
                      "synthetic (a rendered world that reacts to the robot's moves), camera "
                      "(the RealSense over UVC/V4L2) or recorded:DIR; default: the config's");
  command->add_flag("--dry-run", request->dry_run,
                    "send nothing to the robot; the synthetic world then sees the robot move as "
                    "commanded");
  command->add_option("--robot", request->robot,
                      "the robot's ADDRESS[:PORT], overriding robot.address/robot.port");
  command
      ->add_option("--robot-timeout-ms", request->robot_timeout_ms,
                   "how long to wait for the robot's first state packet before giving up")
      ->check(oasis::cli::whole_in(10, 60000));
  command->add_flag("--fast", request->fast,
                    "with --dry-run and a synthetic or recorded source: do not wait for the "
                    "clock, run each step as soon as the last is done");
  command->footer(
      "Without --dry-run the robot must answer within --robot-timeout-ms, or nothing starts. "
      "The robot stops within " +
      std::to_string(go1::kDefaultWatchdogTimeout.count()) +
      " ms when the loop stalls, and on Ctrl-C, SIGTERM or SIGHUP it is told to stop, then to "
      "stand.");
  return [request] {
    if (request->fast && !request->dry_run)
      throw std::invalid_argument("--fast needs --dry-run: a robot moves in real time");
    return run_session(*request);
  };
}

CommandRunner add_replay_command(CLI::App& app) {
  auto request = std::make_shared<RunRequest>();
  request->replay = true;
  CLI::App* command = app.add_subcommand(
      "replay", "run the loop on a recorded sequence, without a robot, as fast as it computes");
  auto recording = std::make_shared<std::string>();
  command->add_option("recording", *recording, "the recording's folder (hw/camera/README.md)")
      ->required()
      ->check(CLI::ExistingDirectory);
  add_common_options(*command, *request);
  return [request, recording] {
    request->source = "recorded:" + *recording;
    return run_session(*request);
  };
}

}  // namespace oasis::hw::app
