#include "perception/shirt_segmentation.hpp"

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

namespace oasis::hw {
namespace {

cv::Mat colour_mask(const cv::Mat& hsv, const ShirtColour& colour) {
  cv::Mat mask = cv::Mat::zeros(hsv.size(), CV_8UC1);
  cv::Mat band_mask;
  for (const HsvBand& band : colour.bands) {
    cv::inRange(hsv, band.low, band.high, band_mask);
    mask |= band_mask;
  }
  return mask;
}

void clean_up(cv::Mat& mask, const SegmentationConfig& config) {
  if (config.open_kernel_px > 1) {
    const cv::Mat kernel =
        cv::getStructuringElement(cv::MORPH_RECT, {config.open_kernel_px, config.open_kernel_px});
    cv::morphologyEx(mask, mask, cv::MORPH_OPEN, kernel);
  }
  if (config.close_kernel_px > 1) {
    const cv::Mat kernel =
        cv::getStructuringElement(cv::MORPH_RECT, {config.close_kernel_px, config.close_kernel_px});
    cv::morphologyEx(mask, mask, cv::MORPH_CLOSE, kernel);
  }
}

}  // namespace

std::optional<ShirtBlob> find_shirt(const cv::Mat& hsv, const ShirtColour& colour,
                                    const SegmentationConfig& config) {
  cv::Mat mask = colour_mask(hsv, colour);
  clean_up(mask, config);
  // Labelling the whole image was the costliest step of perception (about 2.5 ms per colour at
  // 640x480), so it runs only on the box around the mask's pixels: the components are the
  // same. The box starts on even coordinates so that OpenCV's 2x2-block labelling groups the
  // pixels as it would over the whole image.
  cv::Rect region = cv::boundingRect(mask);
  if (region.empty()) return std::nullopt;
  region = cv::Rect(cv::Point(region.x & ~1, region.y & ~1), region.br());
  ShirtBlob blob;
  cv::Mat labels;
  cv::Mat stats;
  cv::Mat centroids;
  const int count =
      cv::connectedComponentsWithStats(mask(region), labels, stats, centroids, 8, CV_32S);
  for (int label = 1; label < count; ++label) {  // label 0 is the background
    const int area = stats.at<int>(label, cv::CC_STAT_AREA);
    if (area < config.min_blob_area_px || area <= blob.area_px) continue;
    blob.label = label;
    blob.area_px = area;
    blob.box = {region.x + stats.at<int>(label, cv::CC_STAT_LEFT),
                region.y + stats.at<int>(label, cv::CC_STAT_TOP),
                stats.at<int>(label, cv::CC_STAT_WIDTH), stats.at<int>(label, cv::CC_STAT_HEIGHT)};
  }
  if (blob.label == 0) return std::nullopt;
  blob.labels = labels(blob.box - region.tl());
  return blob;
}

}  // namespace oasis::hw
