#include "perception/synthetic_renderer.hpp"

#include <cmath>
#include <limits>
#include <optional>
#include <utility>

#include <opencv2/core.hpp>

#include "perception/tag_bitmap.hpp"

namespace oasis::hw {
namespace {

// BGR colours. Skin and the dark trousers are reddish or dark on purpose: a segmentation that
// keys on hue alone would pick them up with the red shirt.
const cv::Vec3b kRedShirt{35, 35, 190};
const cv::Vec3b kYellowShirt{30, 200, 225};
const cv::Vec3b kTrousers1{80, 45, 35};  // dark blue
const cv::Vec3b kTrousers2{40, 40, 60};  // dark brown
const cv::Vec3b kSkin{140, 170, 215};
const cv::Vec3b kHair{30, 30, 35};
const cv::Vec3b kWall{175, 185, 190};
const cv::Vec3b kFloor{95, 100, 105};

struct Hit {
  double depth_m = std::numeric_limits<double>::infinity();
  cv::Vec3b colour = kWall;
};

// The tag pinned to a shirt: its bitmap and where it sits relative to the person.
struct PinnedTag {
  cv::Mat bitmap;  // 10x10, from libapriltag
  double cell_m = 0.0;
  double centre_height_m = 0.0;
};

std::optional<cv::Vec3b> tag_colour_at(const PinnedTag& tag, double lateral_m, double height_m) {
  const double half_m = 5.0 * tag.cell_m;
  // Bitmap column 0 is on the image's left, which is the robot's +y side.
  const double column = std::floor((half_m - lateral_m) / tag.cell_m);
  const double row = std::floor((tag.centre_height_m + half_m - height_m) / tag.cell_m);
  if (column < 0 || column >= tag.bitmap.cols || row < 0 || row >= tag.bitmap.rows)
    return std::nullopt;
  const std::uint8_t level =
      tag.bitmap.at<std::uint8_t>(static_cast<int>(row), static_cast<int>(column));
  return cv::Vec3b{level, level, level};
}

std::optional<cv::Vec3b> body_colour_at(const PersonBody& body, int person_index, double lateral_m,
                                        double height_m) {
  const double side = std::abs(lateral_m);
  if (height_m < 0.0) return std::nullopt;
  if (height_m < body.trousers_top_m)
    return side <= body.trousers_width_m / 2
               ? std::optional(person_index == 0 ? kTrousers1 : kTrousers2)
               : std::nullopt;
  if (height_m < body.shirt_top_m)
    return side <= body.shirt_width_m / 2
               ? std::optional(person_index == 0 ? kRedShirt : kYellowShirt)
               : std::nullopt;
  const double across = lateral_m / body.head_half_width_m;
  const double up = (height_m - body.head_centre_m) / body.head_half_height_m;
  if (across * across + up * up > 1.0) return std::nullopt;
  const double head_top_m = body.head_centre_m + body.head_half_height_m;
  return height_m > head_top_m - body.hair_below_top_m ? kHair : kSkin;
}

class SceneTracer {
 public:
  SceneTracer(const SyntheticScene& scene, const RenderSettings& settings)
      : scene_(scene), settings_(settings) {
    if (scene.holder != TreatHolder::kNone)
      tag_ = PinnedTag{tag36h11_bitmap(scene.tag.id), scene.tag.black_edge_m / 8.0,
                       scene.tag.centre_height_m};
  }

  Hit trace(double u, double v) const {
    const CameraIntrinsics& k = settings_.intrinsics;
    const Point3 ray =
        robot_direction_from_camera(settings_.mount, {(u - k.cx) / k.fx, (v - k.cy) / k.fy, 1.0});
    const double height_m = settings_.mount.height_m;
    Hit hit;
    if (ray.x > 0) hit.depth_m = settings_.wall_distance_m / ray.x;
    if (ray.z < 0 && -height_m / ray.z < hit.depth_m) hit = {-height_m / ray.z, kFloor};
    if (ray.x <= 0) return hit;
    for (int index = 0; index < 2; ++index) {
      const auto& person = scene_.people[static_cast<std::size_t>(index)];
      if (!person) continue;
      const double depth_m = person->x_m / ray.x;
      if (depth_m <= 0 || depth_m >= hit.depth_m) continue;
      const double lateral_m = depth_m * ray.y - person->y_m;
      const double at_height_m = height_m + depth_m * ray.z;
      if (auto colour = person_colour_at(index, lateral_m, at_height_m)) hit = {depth_m, *colour};
    }
    return hit;
  }

 private:
  std::optional<cv::Vec3b> person_colour_at(int index, double lateral_m, double height_m) const {
    const bool holds_tag = static_cast<int>(scene_.holder) == index + 1;
    if (holds_tag && tag_)
      if (auto colour = tag_colour_at(*tag_, lateral_m, height_m)) return colour;
    return body_colour_at(settings_.body, index, lateral_m, height_m);
  }

  const SyntheticScene& scene_;
  const RenderSettings& settings_;
  std::optional<PinnedTag> tag_;
};

std::uint16_t depth_units(double depth_m, double scale_m_per_unit) {
  const double units = std::round(depth_m / scale_m_per_unit);
  if (units < 1.0 || units > 65535.0) return 0;
  return static_cast<std::uint16_t>(units);
}

void add_colour_noise(cv::Mat& colour, double sigma, cv::RNG& rng) {
  if (sigma <= 0) return;
  cv::Mat noise(colour.size(), CV_16SC3);
  rng.fill(noise, cv::RNG::NORMAL, 0.0, sigma);
  cv::Mat widened;
  colour.convertTo(widened, CV_16SC3);
  widened += noise;
  widened.convertTo(colour, CV_8UC3);  // saturating
}

}  // namespace

Frame render_scene(const SyntheticScene& scene, const RenderSettings& settings,
                   double timestamp_s) {
  const CameraIntrinsics& k = settings.intrinsics;
  Frame frame;
  frame.colour.create(k.height, k.width, CV_8UC3);
  frame.depth.create(k.height, k.width, CV_16UC1);
  frame.depth_scale_m_per_unit = settings.depth_scale_m_per_unit;
  frame.intrinsics = k;
  frame.timestamp_s = timestamp_s;

  cv::RNG rng(scene.seed);
  const SceneTracer tracer(scene, settings);
  for (int v = 0; v < k.height; ++v) {
    auto* colour_row = frame.colour.ptr<cv::Vec3b>(v);
    auto* depth_row = frame.depth.ptr<std::uint16_t>(v);
    for (int u = 0; u < k.width; ++u) {
      const Hit hit = tracer.trace(u, v);
      colour_row[u] = hit.colour;
      double depth_m = hit.depth_m;
      if (depth_m > settings.max_range_m ||
          rng.uniform(0.0, 1.0) < settings.depth_dropout_probability) {
        depth_row[u] = 0;
        continue;
      }
      depth_m += rng.gaussian(settings.depth_noise.sigma_at(depth_m));
      depth_row[u] = depth_units(depth_m, settings.depth_scale_m_per_unit);
    }
  }
  add_colour_noise(frame.colour, settings.colour_noise_sigma, rng);
  return frame;
}

SyntheticFrameSource::SyntheticFrameSource(std::vector<SyntheticScene> scenes,
                                           RenderSettings settings, double period_s)
    : scenes_(std::move(scenes)), settings_(std::move(settings)), period_s_(period_s) {}

NextFrame SyntheticFrameSource::next() {
  if (next_index_ >= scenes_.size())
    return SourceStop{SourceStop::Kind::kEnd, "all synthetic scenes played"};
  const double timestamp_s = period_s_ * static_cast<double>(next_index_);
  return render_scene(scenes_[next_index_++], settings_, timestamp_s);
}

}  // namespace oasis::hw
