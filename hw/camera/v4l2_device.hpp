#pragma once
// An open V4L2 video-capture node (Linux), closed on destruction. Opening checks, in order,
// that the path exists, is a device, answers V4L2's capability query, and can capture and
// stream video; each failure throws CameraError naming the device and what to check. The V4L2
// structures stay in the .cpp files.

#include <string>
#include <string_view>

namespace oasis::hw::camera {

class V4l2Device {
 public:
  // role names the stream in messages ("colour", "depth").
  V4l2Device(std::string path, std::string_view role);
  ~V4l2Device();
  V4l2Device(const V4l2Device&) = delete;
  V4l2Device& operator=(const V4l2Device&) = delete;

  int descriptor() const { return descriptor_; }
  // "depth device /dev/video0 (Intel(R) RealSense(TM) Depth Ca)": the start of every message.
  const std::string& description() const { return description_; }

  // ioctl(2) on the device, repeated when a signal interrupts it; 0 or -1 with errno set.
  int io_control(unsigned long request, void* argument) const;

 private:
  int descriptor_ = -1;
  std::string description_;
};

// The hint every "cannot find / cannot use the device" message ends with.
inline constexpr std::string_view kListDevicesHint =
    "is the camera plugged in? `v4l2-ctl --list-devices` lists its video nodes";

}  // namespace oasis::hw::camera
