#pragma once
// One trial of `oasis-go1 sim`: the hallway world (hw/sim) as the frame source, a dry-run link
// as the robot (its pose follows the commands, as the spec's dynamics assume), the fast or the
// rendered observation path, and the controller of a profile, all driven by run_loop(), the loop
// of `oasis-go1 run`. Every step's record carries the ground truth (log::GroundTruth).
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "log/step_record.hpp"
#include "loop/profile_controller.hpp"
#include "perception/perception.hpp"
#include "sim/hallway_world.hpp"
#include "sim/scenario.hpp"
#include "sim/trial_svg.hpp"

namespace oasis::hw::loop {

struct SimTrialSetup {
  sim::HallwayScenario scenario;
  sim::ObservationPath path = sim::ObservationPath::kFast;
  double period_s = 0.2;  // the loop's, oasis-go1's loop.rate_hz
  CameraIntrinsics intrinsics;
  double depth_scale_m_per_unit = 0.001;
  PerceptionConfig perception;    // the real perception (rendered path); mount and reach for both
  ControllerSettings controller;  // oasis-go1's settings; the profile's options go on top
  std::optional<std::uint64_t> max_steps;  // nothing: the whole trial
};

struct SimTrialResult {
  std::vector<log::StepRecord> records;
  std::vector<sim::TraceStep> trace;  // for the pictures
};

// Throws std::invalid_argument when the catalog lacks the two contexts of the Go1 spec.
SimTrialResult run_sim_trial(const rt::CatalogView& catalog, const SimTrialSetup& setup,
                             const settings::ControllerProfile& controller, std::uint64_t seed);

}  // namespace oasis::hw::loop
