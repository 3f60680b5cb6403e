#include "camera/v4l2_device.hpp"

#include <cerrno>
#include <cstring>
#include <utility>

#include <fcntl.h>
#include <linux/videodev2.h>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "camera/camera_error.hpp"

namespace oasis::hw::camera {

namespace {

std::string open_failure(const std::string& subject, int error) {
  std::string message = "cannot open " + subject + ": " + std::strerror(error) + "; ";
  if (error == EACCES) return message + "is your user in the 'video' group?";
  if (error == EBUSY) return message + "is another program using the camera?";
  return message + std::string(kListDevicesHint);
}

// The capabilities of this node (device_caps) rather than of the whole physical device.
std::uint32_t node_capabilities(const v4l2_capability& capability) {
  if (capability.capabilities & V4L2_CAP_DEVICE_CAPS) return capability.device_caps;
  return capability.capabilities;
}

}  // namespace

V4l2Device::V4l2Device(std::string path, std::string_view role)
    : description_(std::string(role) + " device " + path) {
  // Non-blocking: every wait is a poll() with a timeout, so a silent camera cannot hang us.
  descriptor_ = ::open(path.c_str(), O_RDWR | O_NONBLOCK | O_CLOEXEC);
  if (descriptor_ < 0) throw CameraError(open_failure(description_, errno));
  struct stat status {};
  if (::fstat(descriptor_, &status) != 0 || !S_ISCHR(status.st_mode)) {
    ::close(descriptor_);
    throw CameraError(description_ + " is not a device file; " + std::string(kListDevicesHint));
  }
  v4l2_capability capability{};
  if (io_control(VIDIOC_QUERYCAP, &capability) != 0) {
    const std::string reason = std::strerror(errno);
    ::close(descriptor_);
    throw CameraError(description_ + " is not a V4L2 video device (VIDIOC_QUERYCAP: " + reason +
                      "); " + std::string(kListDevicesHint));
  }
  description_ += " (" + std::string(reinterpret_cast<const char*>(capability.card)) + ")";
  const std::uint32_t caps = node_capabilities(capability);
  if (!(caps & V4L2_CAP_VIDEO_CAPTURE) || !(caps & V4L2_CAP_STREAMING)) {
    ::close(descriptor_);
    throw CameraError(description_ +
                      " cannot capture and stream video (a metadata or output node?); "
                      "`v4l2-ctl --list-devices` lists the camera's nodes and "
                      "`v4l2-ctl -d <node> --list-formats-ext` what each one offers");
  }
}

V4l2Device::~V4l2Device() {
  if (descriptor_ >= 0) ::close(descriptor_);
}

int V4l2Device::io_control(unsigned long request, void* argument) const {
  int result = 0;
  do {
    result = ::ioctl(descriptor_, request, argument);
  } while (result != 0 && errno == EINTR);
  return result;
}

}  // namespace oasis::hw::camera
