// The YAML layout of Go1Settings, written once: every section and key in file order, the field
// it sets, its codec (type and range, codecs.hpp) and its comment. The reader, the writer, the
// checks and the comparison are visitors of describe(), so a key cannot exist in one and not
// in another. A visitor provides
//   section(key, comment, body)            a nested mapping; body() describes its keys
//   value(key, field, codec, comment)      a scalar
//   bands(key, field, comment)             a list of HSV bands, [{low: [h, s, v], high: [...]}]
//   actions(key, field, comment)           the action -> velocity mapping
// S is Go1Settings (reader) or const Go1Settings (writer, checks).
#pragma once

#include <numbers>

#include "settings/go1_codecs.hpp"
#include "settings/settings.hpp"

namespace oasis::hw::settings::detail {

inline const EnumCodec<go1::GaitType> kGaitCodec{{{"idle", go1::GaitType::kIdle},
                                                  {"trot", go1::GaitType::kTrot},
                                                  {"trot_running", go1::GaitType::kTrotRunning},
                                                  {"climb_stair", go1::GaitType::kClimbStair},
                                                  {"trot_obstacle", go1::GaitType::kTrotObstacle}}};
inline const EnumCodec<MissingHuman> kMissingHumanCodec{
    {{"hold_last", MissingHuman::kHoldLast}, {"outside", MissingHuman::kOutside}}};

// The trot ranges of comm.h (FACTS §1 "Documented ranges"), as go1::check_limits() has them.
inline constexpr double kTrotMaxForward = 1.5;
inline constexpr double kTrotMaxBackward = 1.1;
inline constexpr double kTrotMaxLateral = 1.0;
inline constexpr double kTrotMaxYawRate = 4.0;

// tag36h11 has 587 codes (FACTS §3).
inline constexpr int kTag36h11Codes = 587;

template <class V, class S>
void describe(V& v, S& s) {
  v.section(
      "robot",
      "The Go1 high-level (sport mode) UDP link, hw/go1/README.md. Addresses, ports and the level\n"
      "flag: FACTS §1 (hw/FACTS.md). The fail-safe: with no new\n"
      "command for watchdog_ms the sender stops (walks at zero velocity) for stop_hold_ms, then\n"
      "stands; SIGINT/SIGTERM stop, then stand for shutdown_stand_ms, then the link closes.",
      [&] {
        v.value("address", s.link.robot.address, Ipv4Codec{},
                "sport mode; 192.168.12.1 over the robot's Wi-Fi");
        v.value("port", s.link.robot.port, IntegerCodec<std::uint16_t>{1, 65535},
                "the sport-mode UDP port (SDK udp.h)");
        v.value("local_address", s.link.local.address, Ipv4Codec{},
                "this PC's address to bind; 0.0.0.0: every interface");
        v.value("local_port", s.link.local.port, IntegerCodec<std::uint16_t>{0, 65535},
                "SDK C++ example 8090, Python one 8080; 0: any");
        v.value("level_flag", s.link.level_flag, ByteCodec{},
                "0xee (SDK) or 0x00 (free-dog-sdk): unconfirmed");
        v.value("state_level_flag", s.link.state_level_flag, AnyOrCodec<ByteCodec, std::uint8_t>{},
                "the level flag a HighState must carry, or any");
        v.value("check_state_crc", s.link.check_state_crc, BoolCodec{},
                "refuse HighState packets whose CRC is wrong");
        v.value("rate_hz", s.link.rate_hz, closed<double>(1.0, 1000.0),
                "HighCmd packets per second, as the SDK example");
        v.value("watchdog_ms", s.link.watchdog_timeout, MillisecondsCodec{50, 1000},
                "no new command for this long: stop, then stand");
        v.value("stop_hold_ms", s.link.stop_hold, MillisecondsCodec{0, 5000},
                "stop (zero velocity) this long, then stand");
        v.value("shutdown_stand_ms", s.link.shutdown_stand_hold, MillisecondsCodec{0, 5000},
                "on exit: stand this long, then close the link");
        v.value("gait", s.link.gait, kGaitCodec, "comm.h gaitType; limits: assumes trot");
      });

  v.section(
      "limits",
      "What the sender lets through (hw/go1/motion_limits.hpp): every command is clamped to\n"
      "these speeds, then ramped at these accelerations. Conservative indoor values inside the\n"
      "trot ranges comm.h documents (forward 1.5, backward 1.1, lateral 1.0 m/s; yaw 4 rad/s).",
      [&] {
        auto& limits = s.link.limits;
        v.value("max_forward", limits.max_forward, closed<float>(0.0, kTrotMaxForward),
                "m/s ahead");
        v.value("max_backward", limits.max_backward, closed<float>(0.0, kTrotMaxBackward),
                "m/s back, a magnitude");
        v.value("max_lateral", limits.max_lateral, closed<float>(0.0, kTrotMaxLateral),
                "m/s to either side");
        v.value("max_yaw_rate", limits.max_yaw_rate, closed<float>(0.0, kTrotMaxYawRate),
                "rad/s either way");
        v.value("max_linear_acceleration", limits.max_linear_acceleration, positive<float>(),
                "m/s^2: the ramp of forward and lateral");
        v.value("max_yaw_acceleration", limits.max_yaw_acceleration, positive<float>(),
                "rad/s^2: the ramp of the yaw rate");
      });

  v.actions(
      "actions", s.loop.actions,
      "The velocity of each catalog action, body frame: forward (m/s, + ahead), lateral (m/s,\n"
      "+ left), yaw_rate (rad/s, + counter-clockwise = left). From specs/go1_treat.oasis: a step\n"
      "is 0.2 s, walking moves 0.1 m per step (0.5 m/s), turning 0.1 rad (0.5 rad/s). Every\n"
      "catalog action needs an entry and every entry must name a catalog action. A speed beyond\n"
      "limits: is an error: the clamp would change what the policy's action means. This mapping\n"
      "is taken whole (listing any action replaces all six); an absent component is 0.");

  v.section(
      "camera",
      "A RealSense-class camera over plain UVC: colour through OpenCV, the Z16 depth node through\n"
      "raw V4L2 (FACTS §2). Intrinsics and depth scale are not read from the device: the defaults\n"
      "are a D435's 640x480 depth intrinsics; put your unit's factory calibration here.",
      [&] {
        v.value("colour_device", s.camera.colour_device, TextCodec{},
                "the RGB node (a D435's is usually the third)");
        v.value("depth_device", s.camera.depth_device, TextCodec{},
                "the Z16 depth node (usually the first)");
        v.value("fps", s.camera.fps, IntegerCodec<int>{1, 300},
                "both streams; a D435: 6, 15 or 30 at 640x480");
        v.section("intrinsics",
                  "Pinhole intrinsics of the colour image, in pixels; the depth image is\n"
                  "registered to the same pixels.",
                  [&] {
                    auto& k = s.camera.intrinsics;
                    v.value("fx", k.fx, positive<double>(), "focal length, x");
                    v.value("fy", k.fy, positive<double>(), "focal length, y");
                    v.value("cx", k.cx, non_negative<double>(), "principal point, x (< width)");
                    v.value("cy", k.cy, non_negative<double>(), "principal point, y (< height)");
                    v.value("width", k.width, IntegerCodec<int>{1, 4096},
                            "pixels: both streams are opened at this size");
                    v.value("height", k.height, IntegerCodec<int>{1, 4096}, "pixels");
                  });
        v.value("depth_scale_m_per_unit", s.camera.depth_scale_m_per_unit,
                RealCodec<double>{0.0, 1.0, true, false},
                "metres per Z16 count (D4xx but D405: 0.001)");
        v.value("open_timeout_s", s.camera.open_timeout_s, RealCodec<double>{0.0, 60.0, true},
                "wait this long for each stream's first frame");
        v.value("frame_timeout_s", s.camera.frame_timeout_s, RealCodec<double>{0.0, 60.0, true},
                "a stream silent this long has failed");
        v.section("mount", "Where the camera sits on the robot (perception/camera_mount.hpp).",
                  [&] {
                    auto& mount = s.perception.mount;
                    v.value("height_m", mount.height_m, closed<double>(0.0, 2.0),
                            "optical centre above the ground");
                    v.value("pitch_up_rad", mount.pitch_up_rad,
                            closed<double>(-std::numbers::pi / 2, std::numbers::pi / 2),
                            "25 degrees: shirts in view from 0.5 to 4 m");
                  });
      });

  v.section(
      "perception",
      "Two people told apart by shirt colour, placed in the robot frame from depth; the\n"
      "AprilTag (tag36h11) one of them holds is the treat, and the reward is 1 while its holder\n"
      "stands in reach (hw/perception/README.md). Colours are OpenCV 8-bit HSV: hue 0..179\n"
      "(degrees / 2), saturation and value 0..255, bounds inclusive.",
      [&] {
        v.section("segmentation", "A pixel is of a shirt's colour if it lies in any band.", [&] {
          auto& seg = s.perception.segmentation;
          v.bands("red", seg.red.bands, "human 1; hue wraps at 0, so two bands");
          v.bands("yellow", seg.yellow.bands, "human 2");
          v.value("open_kernel_px", seg.open_kernel_px, IntegerCodec<int>{0, 51},
                  "opening removes isolated pixels; 0 or 1: off");
          v.value("close_kernel_px", seg.close_kernel_px, IntegerCodec<int>{0, 51},
                  "closing bridges small gaps; 0 or 1: off");
          v.value("min_blob_area_px", seg.min_blob_area_px, IntegerCodec<int>{1, 16777216},
                  "a smaller blob is not a shirt");
        });
        v.section("localisation", "A shirt blob -> a robot-frame position and a confidence.", [&] {
          auto& loc = s.perception.localisation;
          v.value("shirt_width_m", loc.shirt_width_m, RealCodec<double>{0.0, 2.0, true},
                  "the people's shirt width");
          v.value("min_depth_pixels", loc.min_depth_pixels, IntegerCodec<int>{1, 16777216},
                  "fewer blob pixels with depth: not seen");
          v.value("edge_quantile", loc.edge_quantile, RealCodec<double>{0.0, 0.5, false, true},
                  "lateral extent: this quantile to 1 - it");
          v.value("full_width_fraction", loc.full_width_fraction, RealCodec<double>{0.0, 1.0, true},
                  "narrower than this: the shirt is cut off");
          v.value("edge_strip_px", loc.edge_strip_px, IntegerCodec<int>{1, 1000},
                  "searched beside a blob for a nearer occluder");
          v.value("occluder_margin_m", loc.occluder_margin_m, non_negative<double>(),
                  "an occluder is at least this much nearer");
          v.value("cut_confidence", loc.cut_confidence, closed<double>(0.0, 1.0),
                  "confidence of a centre rebuilt from one edge");
          v.value("dense_sampling_max_area_px", loc.dense_sampling_max_area_px,
                  IntegerCodec<int>{1, 16777216}, "larger blobs: every other pixel");
        });
        v.section("tags", "The libapriltag tag36h11 detector, run on the shirts.", [&] {
          auto& tags = s.perception.tags;
          v.value("max_hamming", tags.max_hamming, IntegerCodec<int>{0, 3},
                  "bit errors accepted (codes are 11 apart)");
          v.value("upsample_below_px", tags.upsample_below_px, non_negative<double>(),
                  "expected tag edge below this: search at 2x");
          v.value("decimate_above_px", tags.decimate_above_px, non_negative<double>(),
                  "above this: quad_decimate 2");
          v.value("roi_margin_px", tags.roi_margin_px, IntegerCodec<int>{0, 1000},
                  "added around each region searched");
        });
        v.value("treat_tag_id", s.perception.treat_tag_id,
                AnyOrCodec<IntegerCodec<int>, int>{{0, kTag36h11Codes - 1}},
                "the tag36h11 id that is the treat, or any");
        v.value("tag_black_edge_m", s.perception.tag_black_edge_m,
                RealCodec<double>{0.0, 2.0, true}, "the printed tag's black square edge");
        v.value("tag_height_m", s.perception.tag_height_m, closed<double>(0.0, 3.0),
                "where holders carry it: its centre above the floor");
        v.value("tag_edge_margin_px", s.perception.tag_edge_margin_px, non_negative<double>(),
                "nearer the image border a tag may not be decoded");
        v.value("tag_range_m", s.perception.tag_range_m, positive<double>(),
                "farther a tag is too small to decode reliably");
        v.value("max_tag_to_human_m", s.perception.max_tag_to_human_m, positive<double>(),
                "a tag farther from everyone is held by nobody");
        v.section("reach",
                  "The reward region of specs/go1_treat.oasis, robot frame (x ahead, y left),\n"
                  "bounds inclusive. It must match the spec's regions: the catalog's rewards\n"
                  "come from those, the observed reward from this.",
                  [&] {
                    auto& reach = s.perception.reach;
                    v.value("x_min_m", reach.x_min_m, closed<double>(-10.0, 10.0), "metres ahead");
                    v.value("x_max_m", reach.x_max_m, closed<double>(-10.0, 10.0), "");
                    v.value("y_min_m", reach.y_min_m, closed<double>(-10.0, 10.0),
                            "metres to the left");
                    v.value("y_max_m", reach.y_max_m, closed<double>(-10.0, 10.0), "");
                  });
      });

  v.section("loop", "The control loop of oasis-go1: camera -> perception -> filter -> link.", [&] {
    v.value("rate_hz", s.loop.rate_hz, closed<double>(0.01, 100.0),
            "the spec's period 0.2 s; actions: assumes it");
    v.value("catalog", s.loop.catalog, CatalogCodec{},
            "linked (built in), or a path to a .bin catalog");
    v.value("catalog_spec", s.loop.catalog_spec, CatalogSpecCodec{},
            "its spec: linked's, a .oasis path, or any (no check)");
    v.value("missing_human", s.loop.missing_human, kMissingHumanCodec,
            "a person not seen: hold_last or outside");
    v.value("clamp_to_domain", s.loop.clamp_to_domain, BoolCodec{},
            "a person outside the catalog's domain: put at its edge");
    v.value("keepalive_ms", s.loop.keepalive, MillisecondsCodec{5, 500},
            "repeat the command this often between decisions");
    v.value("controller", s.loop.controller, ControllerCodec{},
            "a profile of hw/config/controllers/, or a .yaml path");
  });

  v.value("source", s.source, SourceCodec{}, "synthetic, camera, or recorded:DIR (a recording)");
}

}  // namespace oasis::hw::settings::detail
