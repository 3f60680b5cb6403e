// The hallway scenario as a frame source for oasis-go1's loop: each next() advances the two
// people by one period (the treat changing hands on the trial's schedule), takes the robot's
// pose from the robot backend (a dry run, whose pose follows the loop's commands), and delivers
// the frame, either rendered (the synthetic renderer; the real perception then runs on it) or
// empty on the fast path, where SimulatedPerception answers from the same truth with the
// camera model of sim_camera.hpp. Both paths draw the same numbers from the same streams, so a
// seed gives the same people, hand-offs and noise on either.
//
// The trial ends (SourceStop kEnd) after scenario.trial.duration_s.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "go1/planar_pose.hpp"
#include "perception/frame.hpp"
#include "perception/perception_stage.hpp"
#include "perception/synthetic_scene.hpp"
#include "random/seeded_random.hpp"
#include "sim/hallway_people.hpp"
#include "sim/sim_camera.hpp"
#include "sim/treat_schedule.hpp"

namespace oasis::hw::sim {

enum class ObservationPath { kFast, kRendered };

struct HallwayWorldOptions {
  HallwayScenario scenario;
  std::uint64_t seed = 1;
  double period_s = 0.2;
  SimCamera camera;       // intrinsics, mount, reach from oasis-go1's settings
  RenderSettings render;  // the rendered path; depth noise and dropout set from the scenario
  ObservationPath path = ObservationPath::kFast;
};

// What the world knows about one frame.
struct FrameTruth {
  double time_s = 0.0;
  go1::Pose robot;
  std::array<go1::PlanarPoint, 2> people;  // odometry frame
  TrueScene scene;                         // robot frame, holder, hidden
  bool holder_in_reach = false;            // the true reward is 1 exactly when this holds
};

class HallwayWorld final : public FrameSource {
 public:
  using PoseProvider = std::function<go1::Pose()>;

  HallwayWorld(HallwayWorldOptions options, PoseProvider robot_pose);

  NextFrame next() override;

  const TreatSchedule& schedule() const { return schedule_; }
  const std::optional<FrameTruth>& truth_of_last_frame() const { return last_truth_; }
  const PerceptionResult& observation_of_last_frame() const { return last_observation_; }
  std::uint64_t steps() const;  // frames in one trial

 private:
  FrameTruth truth_at(double time_s, const go1::Pose& robot) const;
  Frame rendered(const FrameTruth& truth) const;

  HallwayWorldOptions options_;
  PoseProvider robot_pose_;
  TreatSchedule schedule_;
  HallwayPeople people_;
  SeededRandom noise_;
  std::uint64_t frames_ = 0;
  std::optional<FrameTruth> last_truth_;
  PerceptionResult last_observation_;
};

// The fast path's perception: the world's observation of the frame it delivered last.
class SimulatedPerception final : public PerceptionStage {
 public:
  explicit SimulatedPerception(const HallwayWorld& world) : world_(world) {}
  PerceptionResult step(const Frame&) override { return world_.observation_of_last_frame(); }

 private:
  const HallwayWorld& world_;
};

}  // namespace oasis::hw::sim
