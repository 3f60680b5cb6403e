#pragma once
// A closed-loop synthetic world for oasis-go1: two people standing at fixed places in the
// odometry frame, the treat handed between them on a schedule, and the robot wherever its pose
// provider says (the fake Go1's odometry, or a dry run's own integration). Each frame is the
// scene rendered from that pose, so what the robot does changes what its camera sees next.
//
// The world's clock is the frame count times the period, not the wall clock: the same seed and
// the same robot poses give the same frames, at any speed the loop runs.
#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "go1/planar_pose.hpp"
#include "perception/frame.hpp"
#include "perception/reach_region.hpp"
#include "perception/synthetic_scene.hpp"
#include "perception/treat_holder.hpp"

namespace oasis::hw::loop {

struct HandOff {
  double at_s = 0.0;  // world time of the hand-off
  TreatHolder to = TreatHolder::kHuman1;
};

struct SyntheticWorldSettings {
  // Odometry frame (the robot starts at the origin facing +x): human 1 ahead and to the left,
  // human 2 ahead and to the right, both in view at the start.
  std::array<PersonPlacement, 2> people{{{2.5, 0.7}, {2.2, -0.8}}};
  TreatHolder first_holder = TreatHolder::kHuman1;
  std::vector<HandOff> hand_offs{{12.0, TreatHolder::kHuman2}, {24.0, TreatHolder::kHuman1}};
  double period_s = 0.2;
  RenderSettings render;
  ReachRegion reach;  // the spec's reward region, for the true reward
  std::uint64_t seed = 1;
};

// What the world knows about the frame it produced last.
struct WorldTruth {
  TreatHolder holder = TreatHolder::kNone;
  bool holder_in_reach = false;                // the true reward is 1 exactly when this holds
  std::array<PersonPlacement, 2> robot_frame;  // both people as the robot's x forward, y left
};

class SyntheticWorld final : public FrameSource {
 public:
  using PoseProvider = std::function<go1::Pose()>;

  SyntheticWorld(SyntheticWorldSettings settings, PoseProvider robot_pose);

  // Never ends: the world runs until the loop stops asking.
  NextFrame next() override;

  const std::optional<WorldTruth>& truth_of_last_frame() const { return last_truth_; }
  TreatHolder holder_at(double time_s) const;

 private:
  SyntheticWorldSettings settings_;
  PoseProvider robot_pose_;
  std::uint64_t frames_ = 0;
  std::optional<WorldTruth> last_truth_;
};

}  // namespace oasis::hw::loop
