#include "sim/hallway_world.hpp"

#include <cmath>
#include <stdexcept>
#include <utility>

#include "perception/synthetic_renderer.hpp"

namespace oasis::hw::sim {
namespace {

constexpr std::uint64_t kNoiseStream = 3;
constexpr double kInFrontM = 0.05;  // the renderer draws only people in front of the camera

std::size_t index_of(TreatHolder holder) {
  return holder == TreatHolder::kHuman2 ? 1 : 0;
}

}  // namespace

HallwayWorld::HallwayWorld(HallwayWorldOptions options, PoseProvider robot_pose)
    : options_(std::move(options)),
      robot_pose_(std::move(robot_pose)),
      schedule_(draw_treat_schedule(options_.scenario, options_.seed)),
      people_(options_.scenario, options_.seed, schedule_.first_holder),
      noise_(SeededRandom::stream(options_.seed, kNoiseStream)) {
  if (!(options_.period_s > 0.0)) throw std::invalid_argument("hallway world: period must be > 0");
  if (!robot_pose_) throw std::invalid_argument("hallway world: no robot pose provider");
  options_.camera.settings = options_.scenario.camera;
  options_.render.depth_noise = options_.scenario.camera.depth_noise;
  options_.render.depth_dropout_probability = options_.scenario.camera.pixel_dropout;
  options_.render.max_range_m = options_.scenario.camera.max_range_m;
}

std::uint64_t HallwayWorld::steps() const {
  return static_cast<std::uint64_t>(
      std::llround(options_.scenario.trial.duration_s / options_.period_s));
}

FrameTruth HallwayWorld::truth_at(double time_s, const go1::Pose& robot) const {
  FrameTruth truth;
  truth.time_s = time_s;
  truth.robot = robot;
  truth.people = people_.positions();
  for (std::size_t i = 0; i < 2; ++i)
    truth.scene.people[i] = go1::to_body_frame(robot, truth.people[i]);
  truth.scene.holder = people_.holder();
  truth.scene.treat_hidden = schedule_.hidden_at(time_s);
  const go1::PlanarPoint& holder = truth.scene.people[index_of(truth.scene.holder)];
  truth.holder_in_reach = options_.camera.reach.contains(holder.x, holder.y);
  return truth;
}

Frame HallwayWorld::rendered(const FrameTruth& truth) const {
  SyntheticScene scene;
  for (std::size_t i = 0; i < 2; ++i) {
    const go1::PlanarPoint& person = truth.scene.people[i];
    if (person.x > kInFrontM) scene.people[i] = PersonPlacement{person.x, person.y};
  }
  scene.holder = truth.scene.treat_hidden ? TreatHolder::kNone : truth.scene.holder;
  scene.seed = options_.seed * 1000003u + frames_;  // fresh pixel noise every frame
  return render_scene(scene, options_.render, truth.time_s);
}

NextFrame HallwayWorld::next() {
  if (frames_ >= steps()) return SourceStop{SourceStop::Kind::kEnd, "the trial is over"};
  const double time_s = static_cast<double>(frames_) * options_.period_s;
  const go1::Pose robot = robot_pose_();
  if (frames_ > 0)
    people_.step(time_s, options_.period_s, robot, schedule_.hand_offs_decided_by(time_s));
  const FrameTruth truth = truth_at(time_s, robot);
  last_observation_ = options_.camera.observe(truth.scene, noise_);
  Frame frame = options_.path == ObservationPath::kRendered ? rendered(truth) : Frame{};
  frame.timestamp_s = time_s;
  last_truth_ = truth;
  ++frames_;
  return frame;
}

}  // namespace oasis::hw::sim
