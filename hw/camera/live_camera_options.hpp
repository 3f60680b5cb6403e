// How to open a RealSense-class camera over plain UVC: the colour node through OpenCV, the
// Z16 depth node through raw V4L2 (OpenCV cannot open it). The intrinsics and depth scale are
// not read from the device (that needs librealsense, not a Debian package): they come from the
// configuration, with the D435's 640x480 values as defaults.
#pragma once

#include <string>

#include "perception/frame.hpp"

namespace oasis::hw::camera {

struct LiveCameraOptions {
  std::string colour_device = "/dev/video4";  // the RGB node of a D435 is usually the 3rd
  std::string depth_device = "/dev/video0";   // the Z16 node, usually the 1st
  int fps = 30;
  CameraIntrinsics intrinsics;  // width and height here are the size both streams are opened at
  double depth_scale_m_per_unit = 0.001;
  double open_timeout_s = 2.0;   // how long to wait for the first frame of each stream
  double frame_timeout_s = 0.5;  // a stream silent for longer is a failure (SourceStop)
};

}  // namespace oasis::hw::camera
