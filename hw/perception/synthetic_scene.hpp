// Ground truth for one synthetic frame: where the two people stand, who holds the treat, and
// how the camera and the people look. Positions are robot-frame (x forward, y left, metres)
// and name the centre of the person's front surface (each person is a flat, upright figure
// facing the robot: trousers, shirt, head).
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "perception/camera_mount.hpp"
#include "perception/depth_noise.hpp"
#include "perception/frame.hpp"
#include "perception/treat_holder.hpp"

namespace oasis::hw {

struct PersonPlacement {
  double x_m = 0.0;
  double y_m = 0.0;
};

// Body proportions, metres above the ground; shared by renderer and perception (shirt width).
struct PersonBody {
  double trousers_top_m = 0.8;
  double trousers_width_m = 0.36;
  double shirt_top_m = 1.4;
  double shirt_width_m = 0.45;
  double head_centre_m = 1.55;
  double head_half_height_m = 0.13;
  double head_half_width_m = 0.10;
  double hair_below_top_m = 0.06;  // the top of the head is dark hair, the rest skin
};

// The AprilTag (tag36h11) pinned to the holder's shirt, facing the robot.
struct TreatTag {
  int id = 0;
  double black_edge_m = 0.20;  // edge of the black square, as apriltag's tagsize
  double centre_height_m = 1.1;
};

struct SyntheticScene {
  std::array<std::optional<PersonPlacement>, 2> people;  // [0] human 1 (red), [1] human 2
  TreatHolder holder = TreatHolder::kNone;
  TreatTag tag;
  std::uint64_t seed = 1;  // noise is a function of the seed only
};

struct RenderSettings {
  CameraIntrinsics intrinsics;
  CameraMount mount;
  PersonBody body;
  double depth_scale_m_per_unit = 0.001;
  double wall_distance_m = 6.0;            // a wall across the room, in front of the robot
  double max_range_m = 10.0;               // beyond this the depth image holds 0
  DepthNoise depth_noise;                  // zero by default: exact depth up to quantisation
  double depth_dropout_probability = 0.0;  // pixels with no depth, as stereo holes
  double colour_noise_sigma = 3.0;         // per channel, 8-bit levels
};

}  // namespace oasis::hw
