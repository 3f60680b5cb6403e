// The live camera's error paths (no camera exists here or in CI): every bad device is refused
// at once with a message naming the device and what to check, and nothing waits.
#include "camera/live_camera.hpp"

#include <chrono>
#include <string>

#include <gtest/gtest.h>

#include "camera/camera_error.hpp"
#include "camera/v4l2_depth_stream.hpp"
#include "temporary_folder.hpp"

namespace oasis::hw::camera {
namespace {

using testing::TemporaryFolder;
using testing::write_text;

constexpr const char* kNoSuchDevice = "/dev/oasis-test-no-such-video";

// The message of the CameraError `open` throws, checked to come quickly.
template <typename Open>
std::string error_of(Open open) {
  const auto start = std::chrono::steady_clock::now();
  std::string message = "no error";
  try {
    open();
  } catch (const CameraError& error) {
    message = error.what();
  }
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(1));
  return message;
}

std::string live_camera_error(const std::string& colour, const std::string& depth) {
  LiveCameraOptions options;
  options.colour_device = colour;
  options.depth_device = depth;
  return error_of([&] { LiveCamera camera(options); });
}

std::string depth_stream_error(const std::string& device) {
  return error_of([&] { V4l2DepthStream stream(device, 640, 480, 30); });
}

TEST(LiveCamera, MissingColourDeviceSaysToLookForTheCamera) {
  EXPECT_EQ(live_camera_error(kNoSuchDevice, kNoSuchDevice),
            std::string("cannot open colour device ") + kNoSuchDevice +
                ": No such file or directory; is the camera plugged in? `v4l2-ctl "
                "--list-devices` lists its video nodes");
}

TEST(LiveCamera, NonVideoDeviceIsRefused) {
  EXPECT_EQ(live_camera_error("/dev/null", kNoSuchDevice),
            "colour device /dev/null is not a V4L2 video device (VIDIOC_QUERYCAP: Inappropriate "
            "ioctl for device); is the camera plugged in? `v4l2-ctl --list-devices` lists its "
            "video nodes");
}

TEST(LiveCamera, RegularFileIsRefused) {
  const TemporaryFolder folder;
  write_text(folder / "video0", "");
  EXPECT_EQ(live_camera_error((folder / "video0").string(), kNoSuchDevice),
            "colour device " + (folder / "video0").string() +
                " is not a device file; is the camera plugged in? `v4l2-ctl --list-devices` "
                "lists its video nodes");
}

TEST(LiveCamera, BadOptionsAreRefused) {
  LiveCameraOptions options;
  options.fps = 0;
  EXPECT_EQ(error_of([&] { LiveCamera camera(options); }),
            "live camera options need a positive size, fps, depth scale and timeouts (got "
            "640x480 at 0 fps)");
  options = {};
  options.frame_timeout_s = 0.0;
  EXPECT_NE(error_of([&] { LiveCamera camera(options); }).find("timeouts"), std::string::npos);
}

TEST(V4l2DepthStream, MissingDeviceSaysToLookForTheCamera) {
  EXPECT_EQ(depth_stream_error(kNoSuchDevice),
            std::string("cannot open depth device ") + kNoSuchDevice +
                ": No such file or directory; is the camera plugged in? `v4l2-ctl "
                "--list-devices` lists its video nodes");
}

TEST(V4l2DepthStream, NonVideoDeviceIsRefused) {
  EXPECT_NE(depth_stream_error("/dev/null").find("depth device /dev/null is not a V4L2 video"),
            std::string::npos);
}

TEST(V4l2DepthStream, FolderIsRefused) {
  const TemporaryFolder folder;
  EXPECT_NE(depth_stream_error(folder.path().string()).find("cannot open depth device"),
            std::string::npos);
}

}  // namespace
}  // namespace oasis::hw::camera
