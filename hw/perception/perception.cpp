#include "perception/perception.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "perception/tag_visibility.hpp"

namespace oasis::hw {
namespace {

// Median depth over the tag's bounding box, 0 if none: the tag lies flat on a shirt.
double tag_depth_m(const Frame& frame, const TagDetection& tag) {
  std::vector<std::uint16_t> depths;
  const cv::Rect bounds =
      cv::boundingRect(std::vector<cv::Point2f>(tag.corners.begin(), tag.corners.end())) &
      cv::Rect(0, 0, frame.depth.cols, frame.depth.rows);
  for (int v = bounds.y; v < bounds.y + bounds.height; ++v)
    for (int u = bounds.x; u < bounds.x + bounds.width; ++u)
      if (const auto d = frame.depth.at<std::uint16_t>(v, u); d != 0) depths.push_back(d);
  if (depths.empty()) return 0.0;
  auto middle = depths.begin() + static_cast<std::ptrdiff_t>(depths.size() / 2);
  std::nth_element(depths.begin(), middle, depths.end());
  return *middle * frame.depth_scale_m_per_unit;
}

}  // namespace

Perception::Perception(PerceptionConfig config)
    : config_(std::move(config)), tag_detector_(config_.tags) {}

PerceptionResult Perception::step(const Frame& frame) {
  PerceptionResult result;
  cv::cvtColor(frame.colour, hsv_, cv::COLOR_BGR2HSV);
  const std::array<const ShirtColour*, 2> colours{&config_.segmentation.red,
                                                  &config_.segmentation.yellow};
  for (std::size_t i = 0; i < 2; ++i)
    if (const auto blob = find_shirt(hsv_, *colours[i], config_.segmentation))
      result.humans[i] = localise_shirt(frame, config_.mount, *blob, config_.localisation);

  // Of all treat tags seen, the clearest one that someone holds decides.
  for (const TagDetection& tag : find_treat_tags(frame, result.humans)) {
    const TreatHolder holder = holder_of(frame, tag, result.humans);
    if (holder == TreatHolder::kNone) continue;
    if (result.treat_tag && result.treat_tag->decision_margin >= tag.decision_margin) continue;
    result.treat_tag = tag;
    result.holder = holder;
  }
  if (result.holder != TreatHolder::kNone) {
    const HumanEstimate& holder = result.humans[person_of_holder(result.holder)];
    result.reward = config_.reach.contains(holder.x_m, holder.y_m) ? 1.0 : 0.0;
  }
  const CarriedTag carried{config_.tag_black_edge_m, config_.tag_height_m,
                           config_.tag_edge_margin_px, config_.tag_range_m};
  mark_tag_visibility(result.humans, frame.intrinsics, config_.mount, carried);
  result.reward_known = reward_is_known(result.humans, result.holder, config_.reach);
  return result;
}

// Searches each seen person's shirt: the treat is pinned there, and a small region is far
// cheaper to search than the whole image.
std::vector<TagDetection> Perception::find_treat_tags(const Frame& frame,
                                                      const std::array<HumanEstimate, 2>& humans) {
  std::vector<TagDetection> tags;
  if (!humans[0].seen && !humans[1].seen) return tags;
  cv::cvtColor(frame.colour, gray_, cv::COLOR_BGR2GRAY);
  for (const HumanEstimate& human : humans) {
    if (!human.seen) continue;
    const double expected_edge_px =
        frame.intrinsics.fx * config_.tag_black_edge_m / std::max(human.depth_m, 0.1);
    for (const TagDetection& tag : tag_detector_.detect(gray_, human.pixel_box, expected_edge_px))
      if (!config_.treat_tag_id || tag.id == *config_.treat_tag_id) tags.push_back(tag);
  }
  return tags;
}

// The person nearest the tag in the robot frame, if near enough. Without depth on the tag,
// the person whose shirt box holds the tag centre (the nearer one if both do).
TreatHolder Perception::holder_of(const Frame& frame, const TagDetection& tag,
                                  const std::array<HumanEstimate, 2>& humans) const {
  const double depth_m = tag_depth_m(frame, tag);
  double best_score = std::numeric_limits<double>::infinity();
  TreatHolder holder = TreatHolder::kNone;
  for (std::size_t i = 0; i < humans.size(); ++i) {
    const HumanEstimate& human = humans[i];
    if (!human.seen) continue;
    double score = 0.0;
    if (depth_m > 0.0) {
      const Point3 at =
          back_project(frame.intrinsics, config_.mount, tag.centre.x, tag.centre.y, depth_m);
      score = std::hypot(at.x - human.x_m, at.y - human.y_m);
      if (score > config_.max_tag_to_human_m) continue;
    } else {
      const cv::Point centre(static_cast<int>(tag.centre.x), static_cast<int>(tag.centre.y));
      if (!human.pixel_box.contains(centre)) continue;
      score = human.depth_m;
    }
    if (score < best_score) {
      best_score = score;
      holder = holder_of_person(i);
    }
  }
  return holder;
}

}  // namespace oasis::hw
