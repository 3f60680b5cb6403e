#include "loop/synthetic_world.hpp"

#include <stdexcept>
#include <utility>

#include "perception/synthetic_renderer.hpp"

namespace oasis::hw::loop {

SyntheticWorld::SyntheticWorld(SyntheticWorldSettings settings, PoseProvider robot_pose)
    : settings_(std::move(settings)), robot_pose_(std::move(robot_pose)) {
  if (!(settings_.period_s > 0.0))
    throw std::invalid_argument("synthetic world: period must be > 0");
  if (!robot_pose_) throw std::invalid_argument("synthetic world: no robot pose provider");
}

TreatHolder SyntheticWorld::holder_at(double time_s) const {
  TreatHolder holder = settings_.first_holder;
  for (const HandOff& hand_off : settings_.hand_offs)
    if (hand_off.at_s <= time_s) holder = hand_off.to;
  return holder;
}

NextFrame SyntheticWorld::next() {
  const double time_s = static_cast<double>(frames_) * settings_.period_s;
  const go1::Pose robot = robot_pose_();

  WorldTruth truth;
  truth.holder = holder_at(time_s);
  SyntheticScene scene;
  for (std::size_t i = 0; i < 2; ++i) {
    const go1::PlanarPoint seen =
        go1::to_body_frame(robot, {settings_.people[i].x_m, settings_.people[i].y_m});
    truth.robot_frame[i] = {seen.x, seen.y};
    scene.people[i] = truth.robot_frame[i];
  }
  scene.holder = truth.holder;
  scene.seed = settings_.seed * 1000003u + frames_;  // fresh noise every frame, fixed per seed
  if (truth.holder != TreatHolder::kNone) {
    const PersonPlacement& holder = truth.robot_frame[truth.holder == TreatHolder::kHuman1 ? 0 : 1];
    truth.holder_in_reach = settings_.reach.contains(holder.x_m, holder.y_m);
  }

  ++frames_;
  last_truth_ = truth;
  return render_scene(scene, settings_.render, time_s);
}

}  // namespace oasis::hw::loop
