// A camera frame as perception sees it, and the interface every frame producer implements
// (the synthetic renderer today, a V4L2 RealSense reader later).
#pragma once

#include <string>
#include <variant>

#include <opencv2/core/mat.hpp>

namespace oasis::hw {

// Pinhole intrinsics of the colour image; the depth image is registered to the same pixels.
// Pixel centres sit at integer coordinates (OpenCV's convention): column u sees the ray
// ((u - cx) / fx, (v - cy) / fy, 1) in the camera's optical frame (x right, y down, z forward).
struct CameraIntrinsics {
  double fx = 382.6;
  double fy = 382.6;
  double cx = 319.0;
  double cy = 246.3;
  int width = 640;
  int height = 480;
};

struct Frame {
  cv::Mat colour;  // CV_8UC3, BGR
  cv::Mat depth;   // CV_16UC1, z-depth along the optical axis; 0 means "no depth"
  double depth_scale_m_per_unit = 0.001;
  CameraIntrinsics intrinsics;
  double timestamp_s = 0.0;
};

// Why a source produced no frame: it ran out (a finished recording or scene list) or it broke.
struct SourceStop {
  enum class Kind { kEnd, kFailure };
  Kind kind = Kind::kEnd;
  std::string reason;
};

using NextFrame = std::variant<Frame, SourceStop>;

class FrameSource {
 public:
  virtual ~FrameSource() = default;
  virtual NextFrame next() = 0;
};

}  // namespace oasis::hw
