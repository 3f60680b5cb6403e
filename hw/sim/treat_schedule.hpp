// When the treat is to change hands, and when it is hidden: drawn once per trial, before
// anything moves, from the trial's own random stream, so that every controller run on the trial
// faces the same decisions and the same hiding, whatever the robot does (with hand-offs by
// meeting, the moment the treat passes still depends on where everyone walks).
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
  std::vector<double> hand_off_s;    // increasing; a hand-off is decided at each
  std::vector<TimeInterval> hidden;  // the holder hides the treat (no tag in view)

  // The hand-offs decided by `time_s` (when they are carried out: HallwayPeople).
  int hand_offs_decided_by(double time_s) const;
  // Who holds the treat at `time_s` if every hand-off is carried out at once (HandOffStyle
  // kInstant).
  TreatHolder holder_at(double time_s) const;
  bool hidden_at(double time_s) const;
};

TreatSchedule draw_treat_schedule(const HallwayScenario& scenario, std::uint64_t seed);

}  // namespace oasis::hw::sim
