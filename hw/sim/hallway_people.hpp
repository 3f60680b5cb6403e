// The two people of the hallway, in the odometry frame (x down the hallway, y to the left).
// Whoever holds the treat behaves as the holder (scenario.holder), the other as the other
// (scenario.other); a hand-off swaps the roles. People react to the robot (the holder waits for
// it, crossings pass in front of it) but draw their choices from their own random stream, so
// that what the camera's noise draws does not change where they walk.
//
// Hand-offs are decided by the trial's schedule and carried out here (scenario.treat.hand_off):
// with kMeet the receiver walks up to the holder, who waits (and after kGiverWaitsS walks toward
// the receiver too), and the treat passes when they are within pass_within_m; so when the treat
// changes hands depends on where everyone is, and holder() is the truth.
#pragma once

#include <array>
#include <cstdint>

#include "go1/planar_pose.hpp"
#include "perception/treat_holder.hpp"
#include "random/seeded_random.hpp"
#include "sim/scenario.hpp"

namespace oasis::hw::sim {

class HallwayPeople {
 public:
  HallwayPeople(const HallwayScenario& scenario, std::uint64_t seed, TreatHolder first_holder);

  // Moves both people over one period of `dt_s` ending at `time_s`, when the schedule has decided
  // `decided_hand_offs` hand-offs so far; those not yet carried out are carried out in turn.
  void step(double time_s, double dt_s, const go1::Pose& robot, int decided_hand_offs);

  // [0] human 1 (red shirt), [1] human 2 (yellow).
  const std::array<go1::PlanarPoint, 2>& positions() const { return positions_; }

  // Who holds the treat now, and how many hand-offs have been carried out.
  TreatHolder holder() const;
  int hand_offs_done() const { return hand_offs_done_; }

 private:
  enum class Behaviour { kWander, kCross, kZigzag, kLeave };

  struct HolderMind {
    bool walking = false;
    double until_s = 0.0;
    double speed_m_s = 0.0;
    double target_y = 0.0;
    double unattended_since_s = -1.0;  // < 0: the robot follows
    bool returning = false;            // coming back in front of the robot
  };

  struct OtherMind {
    Behaviour behaviour = Behaviour::kWander;
    double until_s = 0.0;
    double speed_m_s = 0.0;
    go1::PlanarPoint target;
    double ahead_m = 0.0;  // cross: ahead of the robot; zigzag: behind the holder
    double side = 1.0;     // +1 left wall, -1 right wall
    double next_turn_s = 0.0;
    bool leave_ahead = false;
    bool away = false;  // leave: reached the place out of view
  };

  void start_standing(double time_s);
  void step_back_from(const go1::Pose& robot);
  void step_hand_off(double time_s, double dt_s, const go1::Pose& robot);
  void pass_the_treat(double time_s, const go1::Pose& robot);
  void step_holder(double time_s, double dt_s, const go1::Pose& robot, std::size_t holder);
  bool should_return(double time_s, const go1::Pose& robot, const go1::PlanarPoint& self);
  go1::PlanarPoint in_front_of(const go1::Pose& robot) const;
  void pick_behaviour(double time_s, const go1::Pose& robot);
  go1::PlanarPoint other_target(double time_s, const go1::Pose& robot,
                                const go1::PlanarPoint& holder, const go1::PlanarPoint& self);
  void walk_toward(std::size_t person, const go1::PlanarPoint& target, double distance_m,
                   const go1::Pose& robot);
  double half_width() const;

  HallwayScenario scenario_;
  SeededRandom random_;
  std::array<go1::PlanarPoint, 2> positions_{};
  std::size_t holder_ = 0;  // index of the holder, whose mind is holder_mind_
  int hand_offs_done_ = 0;
  double hand_off_began_s_ = -1.0;  // kMeet: when the receiver set off (< 0: none under way)
  HolderMind holder_mind_;
  OtherMind other_mind_;
};

}  // namespace oasis::hw::sim
