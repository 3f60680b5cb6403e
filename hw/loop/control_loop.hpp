#pragma once
// The loop of oasis-go1: frame -> perception -> filter -> policy -> robot, once per control
// period (0.2 s, the spec's `period`).
//
// Freshness. The Go1 sender's watchdog stops the robot when no command came for
// go1::kDefaultWatchdogTimeout, the length of one control period, so the loop cannot feed it
// only once per decision. Between decisions it repeats the current decision every
// `keepalive_s` (50 ms): a command is "fresh" when the loop that made it is still running.
// Anything that stalls the loop - a camera that stops delivering, a perception step that
// hangs, a debugger - stops the repeats, and the robot stops one watchdog timeout after the
// last one.
//
// Real time or not. On a robot the loop paces itself on the steady clock and `time_s` is wall
// time since the start. On recordings and synthetic dry runs it can run as fast as it computes
// (`realtime = false`): time then advances by exactly one period per step, which makes runs
// reproducible.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "log/step_record.hpp"
#include "loop/loop_controller.hpp"
#include "loop/robot_link.hpp"
#include "perception/frame.hpp"
#include "perception/perception_stage.hpp"

namespace oasis::hw::loop {

struct LoopOptions {
  double period_s = 0.2;
  double keepalive_s = 0.05;
  bool realtime = true;
  std::optional<std::uint64_t> max_steps;  // nothing: until the source ends or a stop request
};

struct LoopParts {
  FrameSource& source;
  PerceptionStage& perception;  // the real Perception, or a simulator's (hw/sim)
  LoopController& controller;   // the AttentionController, or a baseline
  RobotLink& link;
  // The ground truth of the frame just taken, when the source knows it (a simulator).
  std::function<std::optional<log::GroundTruth>()> truth;
  // Called with every step's record (the log writer, a progress line, a test).
  std::function<void(const log::StepRecord&)> on_step;
  // Polled between steps and between keep-alives; true ends the loop (SIGINT/SIGTERM).
  std::function<bool()> stop_requested;
};

enum class LoopEnd { kStepLimit, kSourceEnded, kSourceFailed, kStopRequested };

struct LoopResult {
  LoopEnd end = LoopEnd::kStepLimit;
  std::uint64_t steps = 0;
  std::string reason;  // the source's reason when it ended or failed
};

// Runs until an end condition; does not shut the link down (the caller does, whatever the
// end). Throws std::invalid_argument for a non-positive period or keep-alive.
LoopResult run_loop(LoopParts& parts, const LoopOptions& options);

}  // namespace oasis::hw::loop
