// The YAML layout of HallwayScenario, written once: every section and key in file order, the
// field it sets, its codec (type and range) and its comment. The reader, the writer and the
// comparison are visitors of describe() (hw/yaml_schema/schema_reader.hpp, schema_writer.hpp),
// so a key cannot exist in one and not in the others.
#pragma once

#include <string>
#include <vector>

#include "sim/scenario.hpp"
#include "yaml_schema/codecs.hpp"
#include "yaml_schema/cross_problem.hpp"

namespace oasis::hw::sim::detail {

using yaml_schema::closed;
using yaml_schema::IntegerCodec;
using yaml_schema::non_negative;
using yaml_schema::positive;
using yaml_schema::RealCodec;

inline const yaml_schema::EnumCodec<HandOffStyle> kHandOffCodec{
    {{"meet", HandOffStyle::kMeet}, {"instant", HandOffStyle::kInstant}}};

inline RealCodec<double> probability() {
  return {0.0, 1.0, false, true};
}

template <class V, class S>
void describe(V& v, S& s) {
  v.section("trial", "One trial of the Go1 treat experiment.", [&] {
    v.value("duration_s", s.trial.duration_s, closed<double>(1.0, 3600.0),
            "the paper's one-minute trials");
  });

  v.section("hallway",
            "A straight hallway along the odometry x axis; the robot starts on its centre line at\n"
            "x = 0 facing down it, at the speeds of hw/config/go1.yaml's actions: (the spec's).",
            [&] {
              v.value("width_m", s.hallway.width_m, closed<double>(1.0, 20.0), "wall to wall");
              v.value("wall_margin_m", s.hallway.wall_margin_m, non_negative<double>(),
                      "people keep this far from the walls");
              v.value("robot_margin_m", s.hallway.robot_margin_m, non_negative<double>(),
                      "people keep this far from the robot");
            });

  v.section(
      "holder",
      "Whoever holds the treat stays roughly ahead of the robot: stands (exponential time,\n"
      "mean_stand_s), walks on down the hallway (mean_walk_s, a speed drawn per walk), waits\n"
      "when farther than wait_beyond_m from the robot. Farther than return_beyond_m, or\n"
      "unattended for max_wait_s (farther than wait_beyond_m, or more than\n"
      "facing_half_angle_rad off the robot's heading: the robot is not following), the holder\n"
      "comes back (at return_speed_m_s) to start_min_m in front of the robot, as people call a\n"
      "dog: the paper's protocol keeps the holder in the robot's view. Nobody lets the robot\n"
      "walk into them: nearer than hallway.robot_margin_m, they step back.",
      [&] {
        v.value("start_min_m", s.holder.start_min_m, positive<double>(), "first placed ahead");
        v.value("start_max_m", s.holder.start_max_m, positive<double>(), "");
        v.value("mean_stand_s", s.holder.mean_stand_s, positive<double>(), "");
        v.value("mean_walk_s", s.holder.mean_walk_s, positive<double>(), "");
        v.value("walk_speed_min_m_s", s.holder.walk_speed_min_m_s, non_negative<double>(), "");
        v.value("walk_speed_max_m_s", s.holder.walk_speed_max_m_s, closed<double>(0.0, 3.0),
                "the robot walks at 0.5 m/s");
        v.value("wait_beyond_m", s.holder.wait_beyond_m, positive<double>(),
                "farther from the robot: waits");
        v.value("return_beyond_m", s.holder.return_beyond_m, positive<double>(),
                "farther: comes back in front of the robot");
        v.value("max_wait_s", s.holder.max_wait_s, positive<double>(),
                "unattended this long: comes back likewise");
        v.value("return_speed_m_s", s.holder.return_speed_m_s, positive<double>(),
                "coming back: a brisk walk");
        v.value("facing_half_angle_rad", s.holder.facing_half_angle_rad, closed<double>(0.0, 3.15),
                "the camera's half view is 0.7 rad");
      });

  v.section(
      "other",
      "The other person: one behaviour at a time, picked by these weights (relative), lasting\n"
      "an exponential time (mean_behaviour_s): wander ahead, cross in front of the robot,\n"
      "zig-zag behind the holder, or leave the field of view (behind the robot or far ahead) and\n"
      "come back after away_min_s..away_max_s.",
      [&] {
        v.value("wander_weight", s.other.wander_weight, non_negative<double>(), "");
        v.value("cross_weight", s.other.cross_weight, non_negative<double>(), "");
        v.value("zigzag_weight", s.other.zigzag_weight, non_negative<double>(), "");
        v.value("leave_weight", s.other.leave_weight, non_negative<double>(), "");
        v.value("mean_behaviour_s", s.other.mean_behaviour_s, positive<double>(), "");
        v.value("speed_min_m_s", s.other.speed_min_m_s, non_negative<double>(), "");
        v.value("speed_max_m_s", s.other.speed_max_m_s, closed<double>(0.0, 3.0), "");
        v.value("cross_min_m", s.other.cross_min_m, positive<double>(),
                "crossings pass this far ahead of the robot");
        v.value("cross_max_m", s.other.cross_max_m, positive<double>(), "");
        v.value("zigzag_period_s", s.other.zigzag_period_s, positive<double>(),
                "side to side behind the holder");
        v.value("away_min_s", s.other.away_min_s, non_negative<double>(), "out of view");
        v.value("away_max_s", s.other.away_max_s, non_negative<double>(), "");
      });

  v.section(
      "treat",
      "Hand-offs: a number in hand_offs_min..hand_offs_max per trial, decided at uniform random\n"
      "times between first_after_s and duration - last_before_s, at least min_gap_s apart.\n"
      "hand_off: meet (the receiver walks up to the holder, who waits, and the treat passes\n"
      "within pass_within_m; a hand-off decided before the last is done waits for it) or\n"
      "instant (it changes hands at the decided time wherever the two stand). The holder hides\n"
      "it (no tag in view) hides_per_minute times on average, each for hide_min_s..hide_max_s.",
      [&] {
        v.value("hand_off", s.treat.hand_off, kHandOffCodec, "meet or instant");
        v.value("pass_within_m", s.treat.pass_within_m, closed<double>(0.3, 3.0),
                "arm's reach, centre to centre");
        v.value("hand_offs_min", s.treat.hand_offs_min, IntegerCodec<int>{0, 100}, "");
        v.value("hand_offs_max", s.treat.hand_offs_max, IntegerCodec<int>{0, 100}, "");
        v.value("first_after_s", s.treat.first_after_s, non_negative<double>(), "");
        v.value("last_before_s", s.treat.last_before_s, non_negative<double>(), "");
        v.value("min_gap_s", s.treat.min_gap_s, non_negative<double>(), "");
        v.value("hides_per_minute", s.treat.hides_per_minute, non_negative<double>(), "");
        v.value("hide_min_s", s.treat.hide_min_s, non_negative<double>(), "");
        v.value("hide_max_s", s.treat.hide_max_s, non_negative<double>(), "");
      });

  v.section(
      "camera",
      "The simulated RealSense-class camera (intrinsics and mount: go1.yaml's camera:). On the\n"
      "fast path a person is seen when in range, their shirt at seen_height_m (its centre or\n"
      "either side) projects inside the image, nobody nearer covers occluded_overlap of their\n"
      "width, and no miss is drawn; the position is then the true one with the range perturbed\n"
      "by sigma(d) = a + b d + c d^2 (d: optical depth) and the bearing by bearing_sigma_rad.\n"
      "The tag names the holder when\n"
      "the holder is seen, not hiding it, within tag_range_m, its whole black square in the\n"
      "image (near the robot it leaves the top), and no tag miss is drawn. The defaults are\n"
      "calibrated frame by frame against the rendered path (docs/RESULTS.md).",
      [&] {
        v.value("min_range_m", s.camera.min_range_m, non_negative<double>(), "");
        v.value("max_range_m", s.camera.max_range_m, positive<double>(),
                "D4xx depth is usable to about 6 m");
        v.value("seen_height_m", s.camera.seen_height_m, closed<double>(0.0, 2.0),
                "the lower part of the shirt");
        v.value("edge_margin_px", s.camera.edge_margin_px, non_negative<double>(), "");
        v.value("occluded_overlap", s.camera.occluded_overlap, closed<double>(0.0, 1.0),
                "as the rendered path's perception");
        v.value("miss_probability", s.camera.miss_probability, probability(),
                "per person and frame: blur, glare");
        v.value("depth_noise_a_m", s.camera.depth_noise.constant_m, non_negative<double>(),
                "a: 2 mm");
        v.value("depth_noise_b", s.camera.depth_noise.linear, non_negative<double>(),
                "b: 0.2% of d");
        v.value("depth_noise_c_per_m", s.camera.depth_noise.quadratic, non_negative<double>(),
                "c: 0.5% of d^2 (9 cm at 4 m)");
        v.value("bearing_sigma_rad", s.camera.bearing_sigma_rad, non_negative<double>(),
                "about 4 px");
        v.value("tag_range_m", s.camera.tag_range_m, positive<double>(),
                "a 0.2 m tag is about 19 px there");
        v.value("tag_miss_probability", s.camera.tag_miss_probability, probability(),
                "0: the rendered path has neither");
        v.value("pixel_dropout", s.camera.pixel_dropout, probability(),
                "rendered path: pixels without depth");
      });
}

// The problems between keys of a scenario whose keys are each valid on their own.
std::vector<yaml_schema::CrossProblem> cross_check(const HallwayScenario& scenario);

}  // namespace oasis::hw::sim::detail
