// One perception step: colour + depth frame in; the two people's robot-frame positions, who
// holds the treat (the AprilTag), and the reward of specs/go1_treat.oasis out.
#pragma once

#include <array>
#include <optional>

#include <opencv2/core/mat.hpp>

#include "perception/camera_mount.hpp"
#include "perception/frame.hpp"
#include "perception/human_estimate.hpp"
#include "perception/perception_result.hpp"
#include "perception/perception_stage.hpp"
#include "perception/reach_region.hpp"
#include "perception/shirt_localisation.hpp"
#include "perception/shirt_segmentation.hpp"
#include "perception/tag_detector.hpp"
#include "perception/treat_holder.hpp"

namespace oasis::hw {

struct PerceptionConfig {
  CameraMount mount;
  SegmentationConfig segmentation;
  LocalisationConfig localisation;
  TagDetectorConfig tags;
  std::optional<int> treat_tag_id;  // nothing: any tag36h11 id is the treat
  double tag_black_edge_m = 0.20;   // the printed tag, black square edge
  double tag_height_m = 1.1;        // where holders carry it: its centre above the floor
  double tag_edge_margin_px = 8.0;  // a tag nearer the image border may not be decoded
  double tag_range_m = 4.0;         // a tag farther away is too small to decode reliably
  double max_tag_to_human_m = 0.5;  // a tag farther than this from every person is held by nobody
  ReachRegion reach;
};

class Perception final : public PerceptionStage {
 public:
  explicit Perception(PerceptionConfig config = {});
  PerceptionResult step(const Frame& frame) override;

  const PerceptionConfig& config() const { return config_; }

 private:
  std::vector<TagDetection> find_treat_tags(const Frame& frame,
                                            const std::array<HumanEstimate, 2>& humans);
  TreatHolder holder_of(const Frame& frame, const TagDetection& tag,
                        const std::array<HumanEstimate, 2>& humans) const;

  PerceptionConfig config_;
  TagDetector tag_detector_;
  cv::Mat hsv_;  // scratch images, kept between steps to avoid reallocating
  cv::Mat gray_;
};

}  // namespace oasis::hw
