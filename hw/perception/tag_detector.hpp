// libapriltag's tag36h11 detector, owned (RAII) and run on regions of interest: the people's
// shirts, where the treat must be. Each region gets the detector settings that suit the size the
// tag is expected to have there: a small far tag is upsampled so each bit cell spans a few
// pixels, a large near tag is decimated for speed.
#pragma once

#include <array>
#include <vector>

#include <opencv2/core/mat.hpp>
#include <opencv2/core/types.hpp>

struct apriltag_detector;
struct apriltag_family;

namespace oasis::hw {

struct TagDetectorConfig {
  int max_hamming = 1;               // bit errors accepted (tag36h11 codes are 11 apart)
  double upsample_below_px = 40.0;   // expected tag edge below this: search at 2x
  double decimate_above_px = 100.0;  // expected tag edge above this: quad_decimate 2
  int roi_margin_px = 8;             // added around each region searched
};

struct TagDetection {
  int id = 0;
  int hamming = 0;
  double decision_margin = 0.0;
  cv::Point2d centre;                  // full-image pixels
  std::array<cv::Point2d, 4> corners;  // full-image pixels, in libapriltag's order
};

class TagDetector {
 public:
  explicit TagDetector(TagDetectorConfig config = {});
  ~TagDetector();
  TagDetector(const TagDetector&) = delete;
  TagDetector& operator=(const TagDetector&) = delete;

  // gray: CV_8UC1 of the whole image; region: where to look (clipped to the image);
  // expected_edge_px: the tag's expected black edge in pixels there.
  std::vector<TagDetection> detect(const cv::Mat& gray, cv::Rect region, double expected_edge_px);

 private:
  TagDetectorConfig config_;
  apriltag_family* family_;
  apriltag_detector* detector_;
  cv::Mat upsampled_;
};

}  // namespace oasis::hw
