#include "perception/shirt_localisation.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace oasis::hw {
namespace {

double quantile(std::vector<double>& values, double q) {
  const auto index = static_cast<std::size_t>(q * static_cast<double>(values.size() - 1));
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(index),
                   values.end());
  return values[index];
}

struct BlobSamples {
  std::vector<double> forward_m;
  std::vector<double> lateral_m;
  std::vector<double> depth_m;
  int visited = 0;
};

BlobSamples sample_blob(const Frame& frame, const CameraMount& mount, const ShirtBlob& blob,
                        int step) {
  BlobSamples samples;
  const std::size_t capacity = static_cast<std::size_t>(blob.area_px / (step * step) + 1);
  samples.forward_m.reserve(capacity);
  samples.lateral_m.reserve(capacity);
  samples.depth_m.reserve(capacity);
  for (int v = blob.box.y; v < blob.box.y + blob.box.height; v += step) {
    const int* label_row = blob.labels.ptr<int>(v - blob.box.y);
    const auto* depth_row = frame.depth.ptr<std::uint16_t>(v);
    for (int u = blob.box.x; u < blob.box.x + blob.box.width; u += step) {
      if (label_row[u - blob.box.x] != blob.label) continue;
      ++samples.visited;
      if (depth_row[u] == 0) continue;
      const double depth_m = depth_row[u] * frame.depth_scale_m_per_unit;
      const Point3 point = back_project(frame.intrinsics, mount, u, v, depth_m);
      samples.forward_m.push_back(point.x);
      samples.lateral_m.push_back(point.y);
      samples.depth_m.push_back(depth_m);
    }
  }
  return samples;
}

// Median depth in a strip of columns [first, last) over the blob's rows, or 0 without depth.
double strip_depth(const Frame& frame, const cv::Rect& box, int first, int last) {
  std::vector<double> depths;
  for (int v = box.y; v < box.y + box.height; ++v) {
    const auto* depth_row = frame.depth.ptr<std::uint16_t>(v);
    for (int u = std::max(first, 0); u < std::min(last, frame.depth.cols); ++u)
      if (depth_row[u] != 0) depths.push_back(depth_row[u] * frame.depth_scale_m_per_unit);
  }
  return depths.empty() ? 0.0 : quantile(depths, 0.5);
}

// Whether the shirt may continue past its blob on the image's left (or right) side: the blob
// touches the border there, or something markedly nearer stands right beside it.
bool side_is_cut(const Frame& frame, const cv::Rect& box, bool left, double depth_m,
                 const LocalisationConfig& config) {
  const int strip = config.edge_strip_px;
  if (left ? box.x <= 0 : box.x + box.width >= frame.depth.cols) return true;
  const int first = left ? box.x - strip : box.x + box.width;
  const double beside_m = strip_depth(frame, box, first, first + strip);
  return beside_m > 0.0 && beside_m < depth_m - config.occluder_margin_m;
}

}  // namespace

HumanEstimate localise_shirt(const Frame& frame, const CameraMount& mount, const ShirtBlob& blob,
                             const LocalisationConfig& config) {
  const int step = blob.area_px > config.dense_sampling_max_area_px ? 2 : 1;
  BlobSamples samples = sample_blob(frame, mount, blob, step);
  HumanEstimate estimate;
  const int with_depth = static_cast<int>(samples.depth_m.size());
  if (with_depth < config.min_depth_pixels) return estimate;

  estimate.seen = true;
  estimate.pixel_box = blob.box;
  estimate.x_m = quantile(samples.forward_m, 0.5);
  estimate.depth_m = quantile(samples.depth_m, 0.5);
  // The image's left edge of the blob is the person's extent towards +y.
  const double right_edge_m = quantile(samples.lateral_m, config.edge_quantile);
  const double left_edge_m = quantile(samples.lateral_m, 1.0 - config.edge_quantile);
  const double width_fraction = (left_edge_m - right_edge_m) / config.shirt_width_m;
  const double depth_support = std::min(1.0, 2.0 * with_depth / std::max(samples.visited, 1));
  const double half_width_m = config.shirt_width_m / 2;

  estimate.y_m = (left_edge_m + right_edge_m) / 2;
  if (width_fraction >= config.full_width_fraction) {
    estimate.confidence = std::min(1.0, width_fraction) * depth_support;
    return estimate;
  }
  const bool left_cut = side_is_cut(frame, blob.box, true, estimate.depth_m, config);
  const bool right_cut = side_is_cut(frame, blob.box, false, estimate.depth_m, config);
  if (left_cut != right_cut) {
    estimate.y_m = left_cut ? right_edge_m + half_width_m : left_edge_m - half_width_m;
    estimate.confidence = config.cut_confidence * depth_support;
  } else {
    // Cut on both sides, or narrow for no visible reason: the centre is a guess.
    estimate.confidence = 0.5 * std::max(width_fraction, 0.0) * depth_support;
  }
  return estimate;
}

}  // namespace oasis::hw
