#include "sim/sim_camera.hpp"

#include <algorithm>
#include <cmath>

namespace oasis::hw::sim {
namespace {

double range_of(const go1::PlanarPoint& p) {
  return std::hypot(p.x, p.y);
}

// The bearing interval [low, high] (radians, + left) a person's shirt spans.
std::array<double, 2> span(const go1::PlanarPoint& p, double width_m) {
  const double bearing = std::atan2(p.y, p.x);
  const double half = std::atan2(width_m / 2.0, std::max(range_of(p), 1e-6));
  return {bearing - half, bearing + half};
}

}  // namespace

bool SimCamera::projects_inside(const Point3& robot_point) const {
  return projects_inside_image(intrinsics, mount, robot_point, settings.edge_margin_px);
}

CarriedTag SimCamera::carried_tag() const {
  return {tag.black_edge_m, tag.centre_height_m, settings.edge_margin_px, settings.tag_range_m};
}

bool SimCamera::in_view(const go1::PlanarPoint& person) const {
  const double range = range_of(person);
  if (range < settings.min_range_m || range > settings.max_range_m) return false;
  // Perception finds a shirt cut by the image's edge too (it rebuilds the centre from the edge
  // it sees), so either side of the shirt in the image will do.
  const double along = std::max(range, 1e-6);
  const double side_x = -person.y / along * shirt_width_m / 2.0;
  const double side_y = person.x / along * shirt_width_m / 2.0;
  for (const double side : {0.0, -1.0, 1.0})
    if (projects_inside(
            {person.x + side * side_x, person.y + side * side_y, settings.seen_height_m}))
      return true;
  return false;
}

bool SimCamera::tag_in_view(const go1::PlanarPoint& person) const {
  return tag_would_show(intrinsics, mount, carried_tag(), person.x, person.y);
}

bool SimCamera::occluded_by(const go1::PlanarPoint& person, const go1::PlanarPoint& other) const {
  if (range_of(other) >= range_of(person)) return false;
  const std::array<double, 2> mine = span(person, shirt_width_m);
  const std::array<double, 2> theirs = span(other, shirt_width_m);
  const double covered = std::min(mine[1], theirs[1]) - std::max(mine[0], theirs[0]);
  return covered >= settings.occluded_overlap * (mine[1] - mine[0]);
}

PerceptionResult SimCamera::observe(const TrueScene& scene, SeededRandom& noise) const {
  PerceptionResult result;
  for (std::size_t i = 0; i < 2; ++i) {
    const go1::PlanarPoint& person = scene.people[i];
    // Draw every number whether or not it is used, so that one person's visibility does not
    // shift the noise of every later frame.
    const bool missed = noise.chance(settings.miss_probability);
    const double range_error = noise.normal();
    const double bearing_error = noise.normal(0.0, settings.bearing_sigma_rad);
    if (missed || !in_view(person) || occluded_by(person, scene.people[1 - i])) continue;
    const double range = range_of(person);
    const double depth =
        camera_point_from_robot(mount, {person.x, person.y, settings.seen_height_m}).z;
    const double seen_range = range + settings.depth_noise.sigma_at(depth) * range_error;
    const double seen_bearing = std::atan2(person.y, person.x) + bearing_error;
    HumanEstimate& estimate = result.humans[i];
    estimate.seen = true;
    estimate.x_m = seen_range * std::cos(seen_bearing);
    estimate.y_m = seen_range * std::sin(seen_bearing);
    estimate.confidence = 1.0;
    estimate.depth_m = depth;
  }
  const bool tag_missed = noise.chance(settings.tag_miss_probability);
  const std::size_t holder = scene.holder == TreatHolder::kHuman1 ? 0 : 1;
  const bool tag_seen = scene.holder != TreatHolder::kNone && !scene.treat_hidden && !tag_missed &&
                        result.humans[holder].seen && tag_in_view(scene.people[holder]);
  if (tag_seen) {
    const HumanEstimate& seen = result.humans[holder];
    result.holder = scene.holder;
    result.reward = reach.contains(seen.x_m, seen.y_m) ? 1.0 : 0.0;
  }
  // As perception decides these, from what it saw.
  mark_tag_visibility(result.humans, intrinsics, mount, carried_tag());
  result.reward_known = reward_is_known(result.humans, result.holder, reach);
  return result;
}

}  // namespace oasis::hw::sim
