#pragma once
// A RealSense-class camera read live over plain UVC, without librealsense: colour through
// OpenCV's V4L2 backend, depth through raw V4L2 (V4l2DepthStream). Each colour frame is paired
// with the newest depth frame and stamped with the steady clock when it is taken.
//
// Not done here (README.md, "Limits"): the intrinsics and depth scale come from the options, not
// the device, and depth is not registered to the colour pixels (the two are separate sensors).

#include <chrono>
#include <memory>

#include <opencv2/core/mat.hpp>

#include "camera/live_camera_options.hpp"
#include "camera/v4l2_depth_stream.hpp"
#include "perception/frame.hpp"

namespace cv {
class VideoCapture;
}

namespace oasis::hw::camera {

class LiveCamera final : public FrameSource {
 public:
  // Checks both device nodes, opens both streams and waits up to open_timeout_s for a first
  // frame of each. Throws CameraError naming the device and what to check.
  //
  // OpenCV's V4L2 backend waits for a colour frame for OPENCV_VIDEOIO_V4L_SELECT_TIMEOUT whole
  // seconds (10 unless set), read once per process. Unless it is already set, the constructor
  // sets it to frame_timeout_s rounded up, so a silent colour stream is noticed that soon.
  explicit LiveCamera(LiveCameraOptions options);
  ~LiveCamera() override;
  LiveCamera(const LiveCamera&) = delete;
  LiveCamera& operator=(const LiveCamera&) = delete;

  // The next colour frame with the newest depth frame. SourceStop::kFailure (naming the device)
  // when a stream stays silent longer than frame_timeout_s or the device fails.
  NextFrame next() override;

 private:
  void open_colour();
  void wait_for_first_frames();
  cv::Mat take_colour();  // throws CameraError
  cv::Mat take_depth();   // throws CameraError

  LiveCameraOptions options_;
  std::unique_ptr<V4l2DepthStream> depth_;
  std::unique_ptr<cv::VideoCapture> colour_;
  cv::Mat latest_depth_;
  std::chrono::steady_clock::time_point latest_depth_time_;
};

}  // namespace oasis::hw::camera
