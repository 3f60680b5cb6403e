// Finds a shirt of one colour: an HSV threshold (red needs two hue bands because it wraps
// around hue 0), a morphological clean-up, and the largest connected blob above a minimum area.
#pragma once

#include <optional>
#include <vector>

#include <opencv2/core/mat.hpp>
#include <opencv2/core/types.hpp>

namespace oasis::hw {

// OpenCV 8-bit HSV: hue 0..179 (degrees / 2), saturation and value 0..255. Bounds inclusive.
struct HsvBand {
  cv::Scalar low;
  cv::Scalar high;
};

struct ShirtColour {
  std::vector<HsvBand> bands;  // a pixel matches if it lies in any band
};

struct SegmentationConfig {
  // Red: hue within 10 (20 degrees) of 0 either side. Saturation >= 120 keeps out skin
  // (about 90) and value >= 70 keeps out dark brown cloth and shadows.
  ShirtColour red{{{cv::Scalar(0, 120, 70), cv::Scalar(10, 255, 255)},
                   {cv::Scalar(170, 120, 70), cv::Scalar(179, 255, 255)}}};
  // Yellow: hue 20..35 (40..70 degrees), saturated and bright.
  ShirtColour yellow{{{cv::Scalar(20, 120, 90), cv::Scalar(35, 255, 255)}}};
  int open_kernel_px = 3;   // removes isolated noisy pixels
  int close_kernel_px = 7;  // bridges small gaps (colour noise, tag edges) inside a shirt
  int min_blob_area_px = 150;
};

struct ShirtBlob {
  // CV_32S component labels over `box` only (row 0 is image row box.y, column 0 image column
  // box.x): the pixels of the blob are those labelled `label`.
  cv::Mat labels;
  int label = 0;
  cv::Rect box;  // full-image pixels
  int area_px = 0;
};

// hsv: CV_8UC3 from cv::COLOR_BGR2HSV. Returns the largest blob with at least
// config.min_blob_area_px pixels, or nothing.
std::optional<ShirtBlob> find_shirt(const cv::Mat& hsv, const ShirtColour& colour,
                                    const SegmentationConfig& config);

}  // namespace oasis::hw
