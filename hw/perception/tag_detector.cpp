#include "perception/tag_detector.hpp"

#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <new>

#include <apriltag/apriltag.h>
#include <apriltag/tag36h11.h>
#include <opencv2/imgproc.hpp>

namespace oasis::hw {
namespace {

// The bytes of libapriltag's decode table for `family` (its quick_decode_init, 3.x): three
// slots of 16 bytes for each code and each pattern of up to `max_hamming` flipped bits.
std::size_t decode_table_bytes(const apriltag_family_t& family, int max_hamming) {
  const std::size_t codes = family.ncodes;
  const std::size_t bits = family.nbits;
  std::size_t patterns = 1;
  if (max_hamming >= 1) patterns += bits;
  if (max_hamming >= 2) patterns += bits * (bits - 1);
  if (max_hamming >= 3) patterns += bits * (bits - 1) * (bits - 2);
  return codes * patterns * 3 * 16;
}

// libapriltag prints "Failed to allocate hamming decode table" when its table does not fit in
// memory (a tight --memory-budget), goes on without it, and the first detection then reads
// through a null pointer. Tried first here, so that the program reports running out of memory
// (std::bad_alloc) instead; errno is the library's own signal, in case memory ran out between.
void add_family(apriltag_detector_t* detector, apriltag_family_t* family, int max_hamming) {
  void* room = std::malloc(decode_table_bytes(*family, max_hamming));
  if (room == nullptr) throw std::bad_alloc();
  std::free(room);
  errno = 0;
  apriltag_detector_add_family_bits(detector, family, max_hamming);
  if (errno == ENOMEM) throw std::bad_alloc();
}

}  // namespace

TagDetector::TagDetector(TagDetectorConfig config)
    : config_(config), family_(tag36h11_create()), detector_(apriltag_detector_create()) {
  try {
    add_family(detector_, family_, config_.max_hamming);
  } catch (...) {
    apriltag_detector_destroy(detector_);
    tag36h11_destroy(family_);
    throw;
  }
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
