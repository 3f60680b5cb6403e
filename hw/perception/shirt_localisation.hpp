// Turns a shirt blob into a robot-frame position: every blob pixel with depth is back-projected
// and robust statistics are taken (median forward distance; lateral centre from the blob's
// lateral extent). A shirt narrower than it should be is cut off, by the image border or by a
// nearer person; then the centre is rebuilt from the edge that is still true, at lower
// confidence, rather than reported wrong with full confidence.
#pragma once

#include "perception/camera_mount.hpp"
#include "perception/frame.hpp"
#include "perception/human_estimate.hpp"
#include "perception/shirt_segmentation.hpp"

namespace oasis::hw {

struct LocalisationConfig {
  double shirt_width_m = 0.45;             // the people's shirt width (PersonBody's default)
  int min_depth_pixels = 40;               // fewer blob pixels with depth: "not seen"
  double edge_quantile = 0.02;             // lateral extent from the 2% and 98% quantiles
  double full_width_fraction = 0.85;       // narrower than this: the shirt is cut off
  int edge_strip_px = 4;                   // strip beside the blob searched for a nearer occluder
  double occluder_margin_m = 0.15;         // an occluder is at least this much nearer
  double cut_confidence = 0.6;             // confidence of a centre rebuilt from one edge
  int dense_sampling_max_area_px = 20000;  // larger blobs are sampled on every other pixel
};

HumanEstimate localise_shirt(const Frame& frame, const CameraMount& mount, const ShirtBlob& blob,
                             const LocalisationConfig& config);

}  // namespace oasis::hw
