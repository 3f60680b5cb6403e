// Renders a SyntheticScene by casting one ray per pixel against the floor, a wall and the two
// people, so colour and depth agree exactly and occlusion falls out of the nearest hit.
#pragma once

#include <cstddef>
#include <vector>

#include "perception/frame.hpp"
#include "perception/synthetic_scene.hpp"

namespace oasis::hw {

Frame render_scene(const SyntheticScene& scene, const RenderSettings& settings,
                   double timestamp_s = 0.0);

// Plays a list of scenes, one frame each, then reports the end.
class SyntheticFrameSource final : public FrameSource {
 public:
  SyntheticFrameSource(std::vector<SyntheticScene> scenes, RenderSettings settings,
                       double period_s = 0.2);
  NextFrame next() override;

 private:
  std::vector<SyntheticScene> scenes_;
  RenderSettings settings_;
  double period_s_;
  std::size_t next_index_ = 0;
};

}  // namespace oasis::hw
