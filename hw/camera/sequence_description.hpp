#pragma once
// What sequence.yaml says about a recording: the camera (intrinsics, depth scale), when each
// frame was taken, and optionally who held the treat in each frame (ground truth for tests of
// perception on real footage).

#include <cstddef>
#include <vector>

#include "perception/frame.hpp"
#include "perception/treat_holder.hpp"

namespace oasis::hw::camera {

struct SequenceDescription {
  CameraIntrinsics intrinsics;  // width x height is the size of every colour and depth frame
  double depth_scale_m_per_unit = 0.001;
  std::vector<double> timestamps_s;  // one per frame, increasing; its size is the frame count
  std::vector<TreatHolder> truth;    // one per frame, or empty when the recording has no truth

  std::size_t frame_count() const { return timestamps_s.size(); }
  bool has_truth() const { return !truth.empty(); }
};

}  // namespace oasis::hw::camera
