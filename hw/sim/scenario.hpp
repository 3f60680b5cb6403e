// The hallway scenario of the Go1 treat experiment (issue 14): every parameter of the simulator,
// with its default. The YAML layout, key by key with comments, is scenario_schema.hpp; the
// defaults are hw/config/hallway.yaml (a test holds the two equal).
//
// The robot's speeds, the loop rate, the camera's intrinsics and mount and the reach region are
// not here: they are oasis-go1's settings (hw/config/go1.yaml), which the simulated robot,
// camera and reward use as the real ones would.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "perception/depth_noise.hpp"
#include "yaml_schema/settings_error.hpp"

namespace oasis::hw::sim {

struct TrialSettings {
  double duration_s = 60.0;  // the paper's one-minute trials
};

// A straight hallway along the odometry frame's x axis; the robot starts on its centre line at
// x = 0, facing down it.
struct HallwaySettings {
  double width_m = 3.0;          // wall to wall: a wide office corridor
  double wall_margin_m = 0.3;    // people keep this far from the walls
  double robot_margin_m = 0.35;  // people keep this far from the robot, and step back to it
};

// The holder stays roughly ahead of the robot, alternating between standing (when the robot
// can reach them) and walking on down the hallway; one who gets far ahead waits, and one the
// robot does not follow (or a new holder far away) comes back in front of it, as people call
// a dog.
struct HolderSettings {
  double start_min_m = 1.5;  // first placed this far ahead of the robot ...
  double start_max_m = 2.5;  // ... up to this
  double mean_stand_s = 4.0;
  double mean_walk_s = 3.0;
  double walk_speed_min_m_s = 0.2;     // a slow stroll ...
  double walk_speed_max_m_s = 0.6;     // ... to a bit faster than the robot's 0.5 m/s
  double wait_beyond_m = 3.0;          // farther than this from the robot: stops and waits
  double return_beyond_m = 5.0;        // farther than this: comes back in front of the robot
  double max_wait_s = 1.0;             // unattended this long (below): likewise
  double return_speed_m_s = 1.0;       // coming back: a brisk walk, as people calling a dog
  double facing_half_angle_rad = 0.7;  // more than this off the robot's heading: unattended
};

// The other person wanders, crosses in front of the robot, zig-zags behind the holder, or leaves
// the field of view and comes back: one behaviour at a time, each picked with these weights.
struct OtherSettings {
  double wander_weight = 0.3;
  double cross_weight = 0.25;
  double zigzag_weight = 0.25;
  double leave_weight = 0.2;
  double mean_behaviour_s = 5.0;
  double speed_min_m_s = 0.4;
  double speed_max_m_s = 1.0;
  double cross_min_m = 0.8;  // crossings pass this far ahead of the robot ...
  double cross_max_m = 2.0;  // ... up to this
  double zigzag_period_s = 1.5;
  double away_min_s = 2.0;  // out of view this long ...
  double away_max_s = 6.0;  // ... up to this
};

// How the treat changes hands. kMeet: as people pass a treat, at the decided time the receiver
// walks up to the holder, who waits, and the treat passes when the two are within pass_within_m
// of each other. kInstant: it changes hands at the decided time wherever the two stand (an
// unphysical stress case, kept to compare with).
enum class HandOffStyle { kMeet, kInstant };

// Who holds the treat when: 1 to 3 hand-offs per trial decided at random times, and moments when
// the holder hides it.
struct TreatSettings {
  HandOffStyle hand_off = HandOffStyle::kMeet;
  double pass_within_m = 0.8;  // kMeet: centre to centre, arm's reach between two people
  int hand_offs_min = 1;
  int hand_offs_max = 3;
  double first_after_s = 8.0;  // no hand-off before this ...
  double last_before_s = 6.0;  // ... nor this close to the end
  double min_gap_s = 8.0;      // between two hand-offs
  double hides_per_minute = 1.5;
  double hide_min_s = 1.0;
  double hide_max_s = 3.0;
};

// The camera on the fast path: who is seen, and how well. The rendered path renders the same
// scene (pixel_dropout, depth_noise per pixel) and runs the real perception instead.
struct SimCameraSettings {
  double min_range_m = 0.2;
  double max_range_m = 6.0;     // RealSense D4xx depth is usable to about 6 m indoors
  double seen_height_m = 0.9;   // a person is seen when this point of their shirt is in view
  double edge_margin_px = 8.0;  // ... at least this far inside the image
  // Calibrated against the rendered path, frame by frame on the same trials (docs/RESULTS.md,
  // issue 14): the real perception on rendered frames finds a shirt until someone nearer covers
  // nearly all of it, and misses nothing else at random. A real camera's extra misses (motion
  // blur, glare) are miss_probability and tag_miss_probability, 0 so that the two paths agree.
  double occluded_overlap = 0.95;  // hidden when someone nearer covers this much of their width
  double miss_probability = 0.0;   // a person in view is missed anyway
  DepthNoise depth_noise = DepthNoise::realsense_like();  // sigma(d) = a + b d + c d^2
  double bearing_sigma_rad = 0.01;                        // about 4 pixels at 640x480
  double tag_range_m = 4.0;  // a 0.2 m tag is about 19 px wide there: still decoded
  double tag_miss_probability = 0.0;
  double pixel_dropout = 0.02;  // rendered path: pixels without depth
};

struct HallwayScenario {
  TrialSettings trial;
  HallwaySettings hallway;
  HolderSettings holder;
  OtherSettings other;
  TreatSettings treat;
  SimCameraSettings camera;
};

// Reads a scenario file; absent keys keep their defaults, unknown keys and values out of range
// are errors. Throws yaml_schema::SettingsError (FILE:LINE:COL: error: KEY: MESSAGE, every
// problem).
HallwayScenario load_scenario(const std::filesystem::path& file);
HallwayScenario parse_scenario(std::string_view yaml_text, std::string_view file_name);

// Every key with its value and a comment; scenario_to_yaml(HallwayScenario{}) is
// hw/config/hallway.yaml.
std::string scenario_to_yaml(const HallwayScenario& scenario);

// The keys whose values differ, as dotted paths ("holder.mean_walk_s").
std::vector<std::string> differing_keys(const HallwayScenario& a, const HallwayScenario& b);

}  // namespace oasis::hw::sim
