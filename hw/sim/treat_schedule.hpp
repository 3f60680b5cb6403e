// Who holds the treat when, and when it is hidden: drawn once per trial, before anything moves,
// from the trial's own random stream, so that every controller run on the trial faces the same
// hand-offs and the same hiding, whatever the robot does.
#pragma once

#include <cstdint>
#include <vector>

#include "perception/treat_holder.hpp"
#include "sim/scenario.hpp"

namespace oasis::hw::sim {

struct TimeInterval {
  double begin_s = 0.0;
  double end_s = 0.0;
};

struct TreatSchedule {
  TreatHolder first_holder = TreatHolder::kHuman1;
  std::vector<double> hand_off_s;    // increasing; the treat changes hands at each
  std::vector<TimeInterval> hidden;  // the holder hides the treat (no tag in view)

  TreatHolder holder_at(double time_s) const;
  bool hidden_at(double time_s) const;
};

TreatSchedule draw_treat_schedule(const HallwayScenario& scenario, std::uint64_t seed);

}  // namespace oasis::hw::sim
