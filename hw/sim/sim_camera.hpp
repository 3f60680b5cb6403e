// The fast path's camera: what perception would report for a frame, drawn directly from the
// true scene instead of rendering pixels. Who is seen follows the camera's geometry (the
// intrinsics and mount of oasis-go1's settings, scenario.camera's ranges and occlusion); the
// positions carry the depth noise sigma(d) = a + b d + c d^2 along the ray and a bearing noise;
// the tag names the holder when its whole black square is in the image and near enough; the reward
// is perception's (the seen holder's position in the reach region).
#pragma once

#include <array>

#include "go1/planar_pose.hpp"
#include "perception/camera_mount.hpp"
#include "perception/frame.hpp"
#include "perception/perception.hpp"
#include "perception/reach_region.hpp"
#include "perception/synthetic_scene.hpp"
#include "perception/tag_visibility.hpp"
#include "perception/treat_holder.hpp"
#include "random/seeded_random.hpp"
#include "sim/scenario.hpp"

namespace oasis::hw::sim {

// The truth of one frame, robot frame (x forward, y left).
struct TrueScene {
  std::array<go1::PlanarPoint, 2> people;  // [0] human 1, [1] human 2
  TreatHolder holder = TreatHolder::kNone;
  bool treat_hidden = false;
};

struct SimCamera {
  SimCameraSettings settings;
  CameraIntrinsics intrinsics;
  CameraMount mount;
  ReachRegion reach;
  double shirt_width_m = 0.45;  // for occlusion: perception/synthetic_scene.hpp's PersonBody
  TreatTag tag;                 // where the holder wears it, as the renderer draws it

  // Does this robot-frame point project inside the image, edge_margin_px from its border?
  bool projects_inside(const Point3& robot_point) const;

  // Would the camera see `person` if nobody stood in the way? In range, and the shirt at
  // seen_height_m in the image: its centre or either side (a shirt cut by the image's edge).
  bool in_view(const go1::PlanarPoint& person) const;

  // Is the whole black square of the tag worn by `person` in the image, and near enough to be
  // decoded? Near the robot the tag leaves the top of the image before the shirt does.
  bool tag_in_view(const go1::PlanarPoint& person) const;
  CarriedTag carried_tag() const;  // the tag as perception/tag_visibility.hpp sees it

  // Is `person` hidden behind `other` (nearer, covering occluded_overlap of their width)?
  bool occluded_by(const go1::PlanarPoint& person, const go1::PlanarPoint& other) const;

  // What perception reports, with noise and misses from `noise`.
  PerceptionResult observe(const TrueScene& scene, SeededRandom& noise) const;
};

}  // namespace oasis::hw::sim
