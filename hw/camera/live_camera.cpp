#include "camera/live_camera.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <opencv2/videoio.hpp>

#include "camera/camera_error.hpp"
#include "camera/v4l2_device.hpp"

namespace oasis::hw::camera {

namespace {

using Clock = std::chrono::steady_clock;

std::chrono::milliseconds milliseconds(double seconds) {
  return std::chrono::milliseconds(static_cast<long long>(std::ceil(seconds * 1000.0)));
}

void check_options(const LiveCameraOptions& options) {
  const CameraIntrinsics& k = options.intrinsics;
  if (k.width <= 0 || k.height <= 0 || options.fps <= 0 || options.open_timeout_s <= 0.0 ||
      options.frame_timeout_s <= 0.0 || options.depth_scale_m_per_unit <= 0.0)
    throw CameraError(
        "live camera options need a positive size, fps, depth scale and timeouts (got " +
        std::to_string(k.width) + "x" + std::to_string(k.height) + " at " +
        std::to_string(options.fps) + " fps)");
}

// Must happen before OpenCV first waits on any V4L2 device in this process (it reads it once).
void bound_opencv_colour_wait(double frame_timeout_s) {
  const int seconds = std::max(1, static_cast<int>(std::ceil(frame_timeout_s)));
  ::setenv("OPENCV_VIDEOIO_V4L_SELECT_TIMEOUT", std::to_string(seconds).c_str(), 0);
}

std::string seconds_text(double seconds) {
  std::string text = std::to_string(seconds);
  while (text.back() == '0')
    text.pop_back();
  if (text.back() == '.') text.pop_back();
  return text + " s";
}

}  // namespace

LiveCamera::LiveCamera(LiveCameraOptions options) : options_(std::move(options)) {
  check_options(options_);
  // Checked with our own V4L2 query first: OpenCV's failure says only "cannot open".
  { const V4l2Device colour_check(options_.colour_device, "colour"); }
  const CameraIntrinsics& k = options_.intrinsics;
  depth_ =
      std::make_unique<V4l2DepthStream>(options_.depth_device, k.width, k.height, options_.fps);
  open_colour();
  wait_for_first_frames();
}

LiveCamera::~LiveCamera() = default;

void LiveCamera::open_colour() {
  bound_opencv_colour_wait(options_.frame_timeout_s);
  const CameraIntrinsics& k = options_.intrinsics;
  const std::vector<int> settings = {cv::CAP_PROP_FRAME_WIDTH,  k.width,
                                     cv::CAP_PROP_FRAME_HEIGHT, k.height,
                                     cv::CAP_PROP_FPS,          options_.fps};
  colour_ = std::make_unique<cv::VideoCapture>(options_.colour_device, cv::CAP_V4L2, settings);
  const std::string device = "colour device " + options_.colour_device;
  if (!colour_->isOpened())
    throw CameraError("OpenCV cannot open " + device + " as a colour stream; `v4l2-ctl -d " +
                      options_.colour_device +
                      " --list-formats-ext` should list YUYV or RGB formats");
  const int width = static_cast<int>(colour_->get(cv::CAP_PROP_FRAME_WIDTH));
  const int height = static_cast<int>(colour_->get(cv::CAP_PROP_FRAME_HEIGHT));
  if (width != k.width || height != k.height)
    throw CameraError(device + " streams " + std::to_string(width) + "x" + std::to_string(height) +
                      ", not the configured " + std::to_string(k.width) + "x" +
                      std::to_string(k.height));
}

// A camera takes a moment to start; after that, silence longer than frame_timeout_s is a fault.
void LiveCamera::wait_for_first_frames() {
  const Clock::time_point deadline = Clock::now() + milliseconds(options_.open_timeout_s);
  cv::Mat colour;
  while (!colour_->read(colour))
    if (Clock::now() >= deadline)
      throw CameraError("no frame from colour device " + options_.colour_device + " within " +
                        seconds_text(options_.open_timeout_s) + "; " +
                        std::string(kListDevicesHint));
  std::optional<cv::Mat> depth = depth_->newest(milliseconds(options_.open_timeout_s));
  if (!depth)
    throw CameraError("no frame from " + depth_->description() + " within " +
                      seconds_text(options_.open_timeout_s) + "; is the camera on a USB 3 port? " +
                      std::string(kListDevicesHint));
  latest_depth_ = std::move(*depth);
  latest_depth_time_ = Clock::now();
}

cv::Mat LiveCamera::take_colour() {
  cv::Mat colour;
  if (!colour_->read(colour) || colour.empty())
    throw CameraError("colour device " + options_.colour_device + " went silent (no frame for " +
                      seconds_text(options_.frame_timeout_s) + " or more); " +
                      std::string(kListDevicesHint));
  const CameraIntrinsics& k = options_.intrinsics;
  if (colour.type() != CV_8UC3 || colour.cols != k.width || colour.rows != k.height)
    throw CameraError("colour device " + options_.colour_device +
                      " gave a frame that is not 8-bit BGR of the configured size");
  return colour;
}

// The newest depth frame; the previous one again when none has arrived since, as long as it is
// younger than frame_timeout_s (depth and colour run at the same rate but are not in step).
cv::Mat LiveCamera::take_depth() {
  std::optional<cv::Mat> depth = depth_->newest(std::chrono::milliseconds(0));
  const auto timeout = milliseconds(options_.frame_timeout_s);
  if (!depth && Clock::now() - latest_depth_time_ > timeout) {
    depth = depth_->newest(timeout);
    if (!depth)
      throw CameraError(depth_->description() + " went silent (no frame for " +
                        seconds_text(options_.frame_timeout_s) + " or more); " +
                        std::string(kListDevicesHint));
  }
  if (depth) {
    latest_depth_ = std::move(*depth);
    latest_depth_time_ = Clock::now();
  }
  return latest_depth_.clone();  // each frame owns its pixels, even when one is used twice
}

NextFrame LiveCamera::next() {
  try {
    Frame frame;
    frame.colour = take_colour();
    frame.timestamp_s = std::chrono::duration<double>(Clock::now().time_since_epoch()).count();
    frame.depth = take_depth();
    frame.depth_scale_m_per_unit = options_.depth_scale_m_per_unit;
    frame.intrinsics = options_.intrinsics;
    return frame;
  } catch (const CameraError& error) {
    return SourceStop{SourceStop::Kind::kFailure, error.what()};
  }
}

}  // namespace oasis::hw::camera
