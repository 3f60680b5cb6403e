// One step of the oasis-go1 loop as it is logged (one JSON object per line: step_json.hpp, keys
// and units in README.md) and scored (table2_metrics.hpp): what perception saw, what the filter
// believed and chose, what the robot was told, and, when the frames come from a simulator, the
// ground truth.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace oasis::hw::log {

// One person as perception reported them at this step.
struct ObservedHuman {
  bool seen = false;
  double x_m = 0.0;  // robot frame, x forward, y left; meaningful only when seen
  double y_m = 0.0;
  double confidence = 0.0;  // 0..1
};

// The velocity command the loop asked for (before the link's clamps and ramps).
struct CommandRecord {
  double forward_m_s = 0.0;
  double lateral_m_s = 0.0;
  double yaw_rate_rad_s = 0.0;
};

// What the simulator knows and the robot does not; absent for camera and recorded runs.
struct GroundTruth {
  std::uint32_t abstraction = 0;  // index of the true context (abstraction) in the catalog
  double reward = 0.0;            // the reward of the true state under the true context
};

// What the robot link has seen so far (cumulative counts), when the loop drives a Go1 (the real
// one or the fake); absent in dry runs and replays.
struct LinkRecord {
  std::uint64_t states_received = 0;    // valid HighState packets from the robot
  std::uint64_t states_refused = 0;     // from the robot, but refused (length, head, flag, CRC)
  std::uint64_t datagrams_ignored = 0;  // from anyone but the robot: never decoded
  std::string last_ignored_from;        // "ADDRESS:PORT" of the last of them; "" if none

  // Written out, not defaulted: hw/ros's ROS-facing files include this and compile as C++17.
  bool operator==(const LinkRecord& other) const {
    return states_received == other.states_received && states_refused == other.states_refused &&
           datagrams_ignored == other.datagrams_ignored &&
           last_ignored_from == other.last_ignored_from;
  }
  bool operator!=(const LinkRecord& other) const { return !(*this == other); }
};

struct StepRecord {
  std::uint64_t step = 0;               // 0, 1, 2, ... within one run
  double time_s = 0.0;                  // seconds since the run started (frame time when replayed)
  std::array<ObservedHuman, 2> humans;  // [0] human 1 (red shirt), [1] human 2 (yellow)
  std::vector<double> state;            // the state vector the filter was given (x1 y1 x2 y2)
  int holder = 0;                       // perceived treat holder: 0 nobody, 1 or 2
  double reward = 0.0;                  // the observed reward the filter was given
  std::vector<double> belief;           // over the catalog's abstractions, after this step
  std::uint32_t abstraction = 0;        // the ML abstraction chosen at this step
  std::string abstraction_name;
  std::uint32_t action = 0;  // the catalog action applied next
  std::string action_name;
  CommandRecord command;
  std::string filter_status;  // "ok", "zero_likelihood", ...
  std::optional<GroundTruth> truth;
  std::optional<LinkRecord> link;
};

}  // namespace oasis::hw::log
