// The pictures of a trial, like the paper's figures: above, the true and the inferred treat
// holder and the belief that human 1 holds it, over time; below, the paths of the robot and
// the two people down the hallway. Plain SVG text, written by hand (no plotting library).
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "go1/planar_pose.hpp"

namespace oasis::hw::sim {

struct TraceStep {
  double time_s = 0.0;
  int true_holder = 0;      // 1 or 2: human 1 (red) or human 2 (yellow)
  int inferred_holder = 0;  // the controller's ML context, as 1 or 2
  double belief_human1 = 0.0;
  bool rewarded = false;  // the true reward was 1
  go1::Pose robot;        // odometry frame
  std::array<go1::PlanarPoint, 2> people;
};

// One trial's SVG; `title` heads it.
std::string trial_svg(const std::vector<TraceStep>& trace, const std::string& title,
                      double hallway_width_m);

// Writes `text` to `path` through a temporary file in the same folder and a rename, so that a
// reader never sees half a file. Throws std::runtime_error when it cannot.
void write_file_atomically(const std::filesystem::path& path, const std::string& text);

}  // namespace oasis::hw::sim
