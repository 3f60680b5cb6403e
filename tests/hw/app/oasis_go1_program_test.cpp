// The oasis-go1 program as a user runs it: a dry run that logs and scores, the fake Go1 driven
// over loopback and stopped by SIGTERM or SIGHUP, and clear errors (exit 1) for a malformed config,
// a missing camera and a robot that does not answer - never a moving robot.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include "go1/fake_go1.hpp"

namespace {

namespace fs = std::filesystem;
using std::chrono::milliseconds;

constexpr milliseconds kSchedulingMargin{50};

struct Outcome {
  int status = -1;  // exit status, or -1 when killed by a signal
  int signal = 0;
  std::string output;  // standard output and error together
};

// The process's own folder for the files a test writes, removed with them when the process
// ends (ctest runs each test case in a process of its own).
class ScratchFolder {
 public:
  ScratchFolder()
      : path_(fs::temp_directory_path() /
              ("oasis_go1_program_test_" + std::to_string(::getpid()))) {
    fs::create_directories(path_);
  }
  ~ScratchFolder() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

fs::path scratch(const std::string& name) {
  static const ScratchFolder folder;
  return folder.path() / name;
}

// Runs oasis-go1 with `arguments`; output goes to a file so a chatty run cannot block.
pid_t start(const std::vector<std::string>& arguments, const fs::path& output) {
  const pid_t child = ::fork();
  if (child == 0) {
    std::FILE* out = std::freopen(output.c_str(), "w", stdout);
    if (out == nullptr || ::dup2(::fileno(stdout), 2) < 0) ::_exit(127);
    std::vector<char*> argv{const_cast<char*>(OASIS_GO1_PROGRAM)};
    for (const std::string& argument : arguments)
      argv.push_back(const_cast<char*>(argument.c_str()));
    argv.push_back(nullptr);
    ::execv(OASIS_GO1_PROGRAM, argv.data());
    ::_exit(127);
  }
  return child;
}

Outcome finish(pid_t child, const fs::path& output) {
  Outcome outcome;
  int status = 0;
  ::waitpid(child, &status, 0);
  if (WIFEXITED(status)) outcome.status = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) outcome.signal = WTERMSIG(status);
  std::ifstream in(output);
  std::stringstream text;
  text << in.rdbuf();
  outcome.output = text.str();
  return outcome;
}

Outcome run(const std::vector<std::string>& arguments) {
  const fs::path output = scratch("output.txt");
  return finish(start(arguments, output), output);
}

std::size_t lines_in(const fs::path& file) {
  std::ifstream in(file);
  std::size_t lines = 0;
  for (std::string line; std::getline(in, line);)
    ++lines;
  return lines;
}

fs::path write_config(const std::string& name, const std::string& yaml) {
  const fs::path file = scratch(name);
  std::ofstream(file) << yaml;
  return file;
}

TEST(OasisGo1Program, DryRunOnTheSyntheticWorldLogsEveryStepAndScores) {
  const fs::path log = scratch("dry.jsonl");
  const Outcome dry = run({"run", "--dry-run", "--source", "synthetic", "--fast", "--steps", "150",
                           "--log", log.string(), "--quiet"});
  ASSERT_EQ(dry.status, 0) << dry.output;
  EXPECT_EQ(lines_in(log), 150u);

  const Outcome score = run({"score", "--json", log.string()});
  ASSERT_EQ(score.status, 0) << score.output;
  EXPECT_NE(score.output.find("\"accuracy\""), std::string::npos) << score.output;
  EXPECT_NE(score.output.find("\"normalized_reward\""), std::string::npos) << score.output;
}

TEST(OasisGo1Program, RunsACatalogLoadedFromItsFile) {
  const Outcome loaded =
      run({"run", "--dry-run", "--source", "synthetic", "--fast", "--steps", "5", "--quiet",
           "--catalog", OASIS_SOURCE_DIR "/generated/go1_treat/go1_treat.bin"});
  EXPECT_EQ(loaded.status, 0) << loaded.output;
  EXPECT_NE(loaded.output.find("go1_treat.bin"), std::string::npos) << loaded.output;

  const Outcome missing = run({"run", "--dry-run", "--catalog", scratch("none.bin").string()});
  EXPECT_EQ(missing.status, 1);
  EXPECT_NE(missing.output.find("none.bin"), std::string::npos) << missing.output;
}

TEST(OasisGo1Program, RefusesACatalogCompiledFromAnotherSpec) {
  const std::string shipped_bin = OASIS_SOURCE_DIR "/generated/go1_treat/go1_treat.bin";
  const std::string shipped_spec = OASIS_SOURCE_DIR "/specs/go1_treat.oasis";
  const fs::path edited_spec = scratch("edited.oasis");
  fs::copy_file(shipped_spec, edited_spec, fs::copy_options::overwrite_existing);
  std::ofstream(edited_spec, std::ios::app) << "// edited after the catalog was compiled\n";
  const std::vector<std::string> quick = {"run",    "--dry-run", "--source", "synthetic",
                                          "--fast", "--steps",   "2",        "--quiet"};
  const auto with = [&quick](std::vector<std::string> more) {
    more.insert(more.begin(), quick.begin(), quick.end());
    return run(more);
  };

  EXPECT_EQ(with({"--catalog", shipped_bin, "--catalog-spec", shipped_spec}).status, 0);
  for (const std::string& catalog : {shipped_bin, std::string("linked")}) {
    const Outcome stale = with({"--catalog", catalog, "--catalog-spec", edited_spec.string()});
    EXPECT_EQ(stale.status, 1) << catalog;
    EXPECT_NE(stale.output.find("was compiled from another spec than " + edited_spec.string()),
              std::string::npos)
        << stale.output;
    EXPECT_NE(stale.output.find("loop.catalog_spec"), std::string::npos) << stale.output;
    EXPECT_EQ(with({"--catalog", catalog, "--catalog-spec", "any"}).status, 0) << catalog;
  }
  // The default, "linked": a catalog of another spec is refused before anything else.
  const Outcome other =
      with({"--catalog", OASIS_SOURCE_DIR "/generated/discrete_tracking/discrete_tracking.bin"});
  EXPECT_EQ(other.status, 1);
  EXPECT_NE(other.output.find("than the linked catalog's spec"), std::string::npos) << other.output;
  const Outcome unreadable = with({"--catalog-spec", scratch("none.oasis").string()});
  EXPECT_EQ(unreadable.status, 1);
  EXPECT_NE(unreadable.output.find("cannot read"), std::string::npos) << unreadable.output;
}

TEST(OasisGo1Program, ConfigPrintsTheShippedSettings) {
  const Outcome printed = run({"config", OASIS_SOURCE_DIR "/hw/config/go1.yaml"});
  ASSERT_EQ(printed.status, 0) << printed.output;
  std::ifstream shipped(OASIS_SOURCE_DIR "/hw/config/go1.yaml");
  std::stringstream text;
  text << shipped.rdbuf();
  EXPECT_EQ(printed.output, text.str());
}

TEST(OasisGo1Program, RecordThenReplay) {
  const fs::path folder = scratch("recording");
  fs::remove_all(folder);
  const Outcome recorded = run({"record", folder.string(), "--frames", "12"});
  ASSERT_EQ(recorded.status, 0) << recorded.output;
  const fs::path log = scratch("replay.jsonl");
  const Outcome replayed = run({"replay", folder.string(), "--log", log.string(), "--quiet"});
  ASSERT_EQ(replayed.status, 0) << replayed.output;
  EXPECT_EQ(lines_in(log), 12u);
}

// `oasis-go1 run` against the fake Go1, ended by `signal_number` after 3 s: it dies of that
// signal, having stopped the robot at once (walking at zero), then told it to stand.
void expect_stop_then_stand_on(int signal_number, const std::string& name) {
  oasis::hw::go1::FakeGo1 robot;
  const std::string address = "127.0.0.1:" + std::to_string(robot.endpoint().port);
  const fs::path config =
      write_config("loopback.yaml", "robot:\n  local_address: 127.0.0.1\n  local_port: 0\n");
  const fs::path output = scratch(name + ".txt");
  const pid_t child = start(
      {"run", "--config", config.string(), "--source", "synthetic", "--robot", address, "--quiet"},
      output);
  std::this_thread::sleep_for(milliseconds(3000));
  const auto signalled = std::chrono::steady_clock::now();
  ASSERT_EQ(::kill(child, signal_number), 0);
  const Outcome outcome = finish(child, output);
  EXPECT_EQ(outcome.signal, signal_number) << "status " << outcome.status << ": " << outcome.output;

  const std::vector<oasis::hw::go1::AppliedCommand> applied = robot.applied_commands();
  ASSERT_FALSE(applied.empty()) << outcome.output;
  bool moved = false;
  for (const auto& command : applied)
    moved = moved || command.command.velocity[0] > 0.0f;
  EXPECT_TRUE(moved) << "the loop never drove the robot forward: " << outcome.output;
  std::optional<std::chrono::steady_clock::time_point> stopped;
  for (const auto& command : applied)
    if (command.at >= signalled && !stopped && command.command.velocity[0] == 0.0f &&
        command.command.velocity[1] == 0.0f && command.command.yaw_speed == 0.0f)
      stopped = command.at;
  ASSERT_TRUE(stopped.has_value()) << outcome.output;
  EXPECT_LE(std::chrono::duration_cast<milliseconds>(*stopped - signalled).count(),
            kSchedulingMargin.count());
  EXPECT_EQ(applied.back().command.mode, oasis::hw::go1::Mode::kIdle);
}

TEST(OasisGo1Program, SigtermStopsThenStandsTheFakeGo1) {
  expect_stop_then_stand_on(SIGTERM, "sigterm");
}

// A closed terminal or ssh session (issue 37, item 2): as SIGTERM, not the default death that
// left the robot walking on its last command.
TEST(OasisGo1Program, SighupStopsThenStandsTheFakeGo1) {
  expect_stop_then_stand_on(SIGHUP, "sighup");
}

TEST(OasisGo1Program, UnreachableRobotIsAnErrorAndNothingRuns) {
  // A fake Go1 that is gone: its port is free, nobody answers.
  std::uint16_t port = 0;
  {
    oasis::hw::go1::FakeGo1 gone;
    port = gone.endpoint().port;
  }
  const fs::path config =
      write_config("unreachable.yaml", "robot:\n  local_address: 127.0.0.1\n  local_port: 0\n");
  const Outcome outcome =
      run({"run", "--config", config.string(), "--source", "synthetic", "--robot",
           "127.0.0.1:" + std::to_string(port), "--robot-timeout-ms", "300", "--quiet"});
  EXPECT_EQ(outcome.status, 1);
  EXPECT_NE(outcome.output.find("did not answer"), std::string::npos) << outcome.output;
}

TEST(OasisGo1Program, MalformedConfigNamesTheKey) {
  const fs::path config = write_config("bad.yaml", "robot:\n  port: 80x2\n");
  const Outcome outcome = run({"run", "--dry-run", "--config", config.string()});
  EXPECT_EQ(outcome.status, 1);
  EXPECT_NE(outcome.output.find("robot.port"), std::string::npos) << outcome.output;
  EXPECT_NE(outcome.output.find("bad.yaml:2:"), std::string::npos) << outcome.output;
}

TEST(OasisGo1Program, SimWritesTable2JsonPerControllerAndLogsThatScoreReads) {
  const fs::path logs = scratch("sim_logs");
  const fs::path plots = scratch("sim_plots");
  const Outcome sim = run({"sim", "--trials", "2", "--steps", "60", "--json", "--logs",
                           logs.string(), "--plots", plots.string()});
  ASSERT_EQ(sim.status, 0) << sim.output;
  for (const char* controller : {"\"oracle\"", "\"paper\"", "\"ours\""})
    EXPECT_NE(sim.output.find(controller), std::string::npos) << controller;
  for (const char* key : {"\"accuracy\"", "\"avg_lag_s\"", "\"max_lag_s\"", "\"normalized_reward\"",
                          "\"mean\"", "\"std\""})
    EXPECT_NE(sim.output.find(key), std::string::npos) << key;
  EXPECT_EQ(lines_in(logs / "ours_trial02.jsonl"), 60u);
  EXPECT_TRUE(fs::exists(plots / "oracle_trial01.svg"));

  const Outcome score = run(
      {"score", (logs / "ours_trial01.jsonl").string(), (logs / "ours_trial02.jsonl").string()});
  ASSERT_EQ(score.status, 0) << score.output;
  EXPECT_NE(score.output.find("reward: truth (truth.reward in 2 of 2 trials)"), std::string::npos)
      << score.output;
  EXPECT_EQ(score.output.find("unavailable"), std::string::npos) << score.output;
}

TEST(OasisGo1Program, SimRefusesAnUnknownController) {
  const Outcome sim = run({"sim", "--controllers", "oracle,psychic"});
  EXPECT_EQ(sim.status, 1);
  EXPECT_NE(sim.output.find("no controller profile \"psychic\"; the shipped ones are oracle, "
                            "paper, guard, no-attention, ours"),
            std::string::npos)
      << sim.output;
}

// The text between `before` and the next `after` in `text`, or "" if absent.
std::string between(const std::string& text, const std::string& before, const std::string& after) {
  const std::size_t start = text.find(before);
  if (start == std::string::npos) return "";
  const std::size_t from = start + before.size();
  const std::size_t end = text.find(after, from);
  return end == std::string::npos ? "" : text.substr(from, end - from);
}

// Issue 22: the controller that `sim` scores is the one `run` drives. Both print the summary of
// the profile they built their controller from (every option that differs from the paper's
// defaults, settings::profile_summary), for a shipped profile and for a file of one's own.
TEST(OasisGo1Program, SimScoresTheControllerThatRunDrives) {
  const fs::path mine = write_config("mine.yaml",
                                     "description: a profile of my own\n"
                                     "filter:\n  mode: noise_aware\n  tie_rule: random\n"
                                     "  seed: 3\n  tie_tolerance: 0.02\n"
                                     "  zero_likelihood_guard: true\n"
                                     "evidence:\n  treat_sighting: 0.8\n");
  for (const std::string& controller : {std::string("ours"), mine.string()}) {
    const Outcome sim =
        run({"sim", "--controllers", controller, "--trials", "1", "--steps", "5", "--json"});
    ASSERT_EQ(sim.status, 0) << sim.output;
    const std::string scored = between(sim.output, "\"options\": \"", "\"");
    const Outcome driven = run({"run", "--dry-run", "--source", "synthetic", "--fast", "--steps",
                                "2", "--quiet", "--controller", controller});
    ASSERT_EQ(driven.status, 0) << driven.output;
    const std::string ran = between(driven.output, ".yaml: ", "); ");
    EXPECT_FALSE(scored.empty()) << sim.output;
    EXPECT_EQ(scored, ran) << controller << "\n" << sim.output << "\n" << driven.output;
  }
  // Without --controller, run drives the settings' loop.controller: ours, what sim measured best.
  const Outcome by_default =
      run({"run", "--dry-run", "--source", "synthetic", "--fast", "--steps", "2", "--quiet"});
  EXPECT_NE(by_default.output.find("controller ours (hw/config/controllers/ours.yaml: "),
            std::string::npos)
      << by_default.output;
}

TEST(OasisGo1Program, RunRefusesTheSimulationBaselines) {
  for (const char* baseline : {"oracle", "no-attention"}) {
    const Outcome outcome = run({"run", "--dry-run", "--source", "synthetic", "--fast", "--steps",
                                 "2", "--quiet", "--controller", baseline});
    EXPECT_EQ(outcome.status, 1) << baseline;
    EXPECT_NE(outcome.output.find("oasis-go1 sim"), std::string::npos) << outcome.output;
  }
}

TEST(OasisGo1Program, MissingCameraNamesTheDevice) {
  const fs::path config = write_config("camera.yaml",
                                       "camera:\n  colour_device: /dev/oasis-no-such-camera\n  "
                                       "depth_device: /dev/oasis-no-such-depth\n");
  const Outcome outcome =
      run({"run", "--dry-run", "--source", "camera", "--config", config.string(), "--quiet"});
  EXPECT_EQ(outcome.status, 1);
  EXPECT_NE(outcome.output.find("/dev/oasis-no-such"), std::string::npos) << outcome.output;
}

}  // namespace
