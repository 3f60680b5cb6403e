#include "perception/tag_detector.hpp"

#include <cstdint>

#include <apriltag/apriltag.h>
#include <apriltag/tag36h11.h>
#include <opencv2/imgproc.hpp>

namespace oasis::hw {

TagDetector::TagDetector(TagDetectorConfig config)
    : config_(config), family_(tag36h11_create()), detector_(apriltag_detector_create()) {
  apriltag_detector_add_family_bits(detector_, family_, config_.max_hamming);
  detector_->nthreads = 1;
}

TagDetector::~TagDetector() {
  apriltag_detector_destroy(detector_);  // before the family it points to
  tag36h11_destroy(family_);
}

std::vector<TagDetection> TagDetector::detect(const cv::Mat& gray, cv::Rect region,
                                              double expected_edge_px) {
  const int margin = config_.roi_margin_px;
  region = cv::Rect(region.x - margin, region.y - margin, region.width + 2 * margin,
                    region.height + 2 * margin) &
           cv::Rect(0, 0, gray.cols, gray.rows);
  if (region.empty()) return {};
  cv::Mat view = gray(region);
  double scale = 1.0;  // searched pixels per image pixel
  if (expected_edge_px < config_.upsample_below_px) {
    cv::resize(view, upsampled_, {}, 2.0, 2.0, cv::INTER_LINEAR);
    view = upsampled_;
    scale = 2.0;
  }
  detector_->quad_decimate = expected_edge_px > config_.decimate_above_px ? 2.0f : 1.0f;

  // libapriltag reads the pixels in place through the row stride; it does not write them.
  image_u8_t image{view.cols, view.rows, static_cast<std::int32_t>(view.step), view.data};
  zarray_t* found = apriltag_detector_detect(detector_, &image);
  // Searched pixel p maps back to image pixel (p + 0.5) / scale - 0.5 (pixel centres).
  const auto to_image = [&](const double* p) {
    return cv::Point2d(region.x + (p[0] + 0.5) / scale - 0.5,
                       region.y + (p[1] + 0.5) / scale - 0.5);
  };
  std::vector<TagDetection> detections;
  for (int i = 0; i < zarray_size(found); ++i) {
    apriltag_detection_t* raw = nullptr;
    zarray_get(found, i, &raw);
    TagDetection detection;
    detection.id = raw->id;
    detection.hamming = raw->hamming;
    detection.decision_margin = raw->decision_margin;
    detection.centre = to_image(raw->c);
    for (std::size_t corner = 0; corner < 4; ++corner)
      detection.corners[corner] = to_image(raw->p[corner]);
    detections.push_back(detection);
  }
  apriltag_detections_destroy(found);
  return detections;
}

}  // namespace oasis::hw
