// oasis-ros's conversion of incoming messages (hw/ros/message_conversion.hpp): a colour image
// (sensor_msgs/Image in any encoding), a depth image, a CameraInfo and a tracker's detections,
// every field taken from the input. The conversion refuses with std::invalid_argument, or
// gives a frame of exactly the declared width x height (CV_8UC3 colour, CV_16UC1 depth,
// intrinsics of that size) that converts back to the same pixels; detections are refused, or
// give a result of the two objects with a holder in range. Nothing else may be thrown.
//
// The input, little-endian, each field read while bytes remain (then 0):
//   image (colour, then depth): encoding index (1 byte, kEncodings), width, height, step (u32
//     each), big-endian flag (1 byte), data length (u32, at most kMostData), fill (1 byte: 0 =
//     the data is the next bytes of the input, as many as remain; else every byte is the next
//     one, so that a short seed can describe the 128 KiB of the crafted frame)
//   camera info: width, height (u32), K (9 doubles)
//   detections: pose count (1 byte, mod 4), x and y of each (doubles), reward (double, or
//     nothing when a flag byte is 0), holder (1 byte, as an int8)
//
// Compiles as C++17, like the edge (ROS 1's message headers).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "fuzz_target.hpp"
#include "ros/message_conversion.hpp"

namespace {

using namespace oasis::hw;
using namespace oasis::hw::ros_node;

const char* const kEncodings[] = {"bgr8",  "rgb8",   "bgra8", "rgba8", "16UC1",
                                  "32FC1", "mono16", "mono8", "",      "8UC3"};
constexpr std::uint32_t kMostData = std::uint32_t{1} << 20;

class Reader {
 public:
  Reader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

  template <class T>
  T next() {
    T value{};
    const std::size_t take = std::min(sizeof(T), size_ - at_);
    std::memcpy(&value, data_ + at_, take);
    at_ += take;
    return value;
  }

  // `count` bytes: the rest of the input (no more than it holds), or one byte repeated.
  std::vector<std::uint8_t> bytes(std::uint32_t count, bool fill) {
    if (fill) return std::vector<std::uint8_t>(count, next<std::uint8_t>());
    const std::size_t take = std::min<std::size_t>(count, size_ - at_);
    std::vector<std::uint8_t> out(data_ + at_, data_ + at_ + take);
    at_ += take;
    return out;
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t at_ = 0;
};

sensor_msgs::Image read_image(Reader& in) {
  sensor_msgs::Image image;
  image.encoding = kEncodings[in.next<std::uint8_t>() % std::size(kEncodings)];
  image.width = in.next<std::uint32_t>();
  image.height = in.next<std::uint32_t>();
  image.step = in.next<std::uint32_t>();
  image.is_bigendian = in.next<std::uint8_t>() & 1;
  const std::uint32_t count = in.next<std::uint32_t>() % (kMostData + 1);
  image.data = in.bytes(count, in.next<std::uint8_t>() != 0);
  return image;
}

sensor_msgs::CameraInfo read_info(Reader& in) {
  sensor_msgs::CameraInfo info;
  info.width = in.next<std::uint32_t>();
  info.height = in.next<std::uint32_t>();
  for (double& k : info.K)
    k = in.next<double>();
  return info;
}

Detections read_detections(Reader& in) {
  Detections detections;
  detections.positions.poses.resize(in.next<std::uint8_t>() % 4);
  for (auto& pose : detections.positions.poses) {
    pose.position.x = in.next<double>();
    pose.position.y = in.next<double>();
  }
  const double reward = in.next<double>();
  if (in.next<std::uint8_t>() != 0) detections.reward = reward;
  detections.holder = static_cast<std::int8_t>(in.next<std::uint8_t>());
  return detections;
}

bool same_pixels(const cv::Mat& a, const cv::Mat& b) {
  if (a.size() != b.size() || a.type() != b.type()) return false;
  const std::size_t row_bytes = static_cast<std::size_t>(a.cols) * a.elemSize();
  for (int row = 0; row < a.rows; ++row)
    if (std::memcmp(a.ptr(row), b.ptr(row), row_bytes) != 0) return false;
  return true;
}

void check_frame(const sensor_msgs::Image& colour, const sensor_msgs::Image& depth,
                 const sensor_msgs::CameraInfo& info) {
  Frame frame;
  try {
    frame = frame_from_messages(colour, depth, info);
  } catch (const std::invalid_argument& e) {
    FUZZ_REQUIRE(std::strlen(e.what()) > 0);
    return;
  }
  FUZZ_REQUIRE(static_cast<std::uint64_t>(frame.colour.cols) == colour.width);
  FUZZ_REQUIRE(static_cast<std::uint64_t>(frame.colour.rows) == colour.height);
  FUZZ_REQUIRE(frame.colour.type() == CV_8UC3);
  FUZZ_REQUIRE(frame.depth.size() == frame.colour.size());
  FUZZ_REQUIRE(frame.depth.type() == CV_16UC1);
  FUZZ_REQUIRE(static_cast<std::uint64_t>(frame.depth.cols) == depth.width);
  FUZZ_REQUIRE(frame.intrinsics.width == frame.colour.cols);
  FUZZ_REQUIRE(frame.intrinsics.height == frame.colour.rows);
  FUZZ_REQUIRE(info.width == 0 || info.width == colour.width);
  // What the node would publish of it (the hallway simulator's direction) reads back the same.
  const CameraMessages again = messages_from_frame(frame, ros::Time(1.0), "camera");
  const Frame back = frame_from_messages(again.colour, again.depth, again.info);
  FUZZ_REQUIRE(same_pixels(back.colour, frame.colour));
  FUZZ_REQUIRE(same_pixels(back.depth, frame.depth));
}

void check_detections(const Detections& detections) {
  PerceptionResult seen;
  try {
    seen = perception_from_detections(detections);
  } catch (const std::invalid_argument&) {
    return;
  }
  FUZZ_REQUIRE(detections.positions.poses.size() == 2);
  const int holder = static_cast<int>(seen.holder);
  FUZZ_REQUIRE(holder >= 0 && holder <= 2);
  for (const HumanEstimate& human : seen.humans)
    FUZZ_REQUIRE(!human.seen || (std::isfinite(human.x_m) && std::isfinite(human.y_m)));
  FUZZ_REQUIRE(std::isfinite(seen.reward));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Reader in(data, size);
  const sensor_msgs::Image colour = read_image(in);
  const sensor_msgs::Image depth = read_image(in);
  const sensor_msgs::CameraInfo info = read_info(in);
  const Detections detections = read_detections(in);
  check_frame(colour, depth, info);
  check_detections(detections);
  return 0;
}
