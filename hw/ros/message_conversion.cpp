#include "ros/message_conversion.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <new>
#include <stdexcept>

#include <cv_bridge/cv_bridge.h>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <sensor_msgs/image_encodings.h>

#include "perception/out_of_memory.hpp"
#include "text/printable_text.hpp"

namespace oasis::hw::ros_node {
namespace {

namespace encodings = sensor_msgs::image_encodings;

constexpr const char* kTruthStatusName = "oasis ground truth";

// No camera gives a side longer than this. The bound keeps every product of two sides and a
// pixel's size far inside 64 bits, and every side inside OpenCV's int.
constexpr std::uint64_t kMaxImageSide = std::uint64_t{1} << 16;

// The bytes of one pixel and of one of its channels, for the encodings we take.
struct PixelLayout {
  std::uint64_t pixel_bytes;
  std::uint64_t channel_bytes;
};

std::string size_text(const sensor_msgs::Image& image) {
  return std::to_string(image.width) + "x" + std::to_string(image.height) + ", step " +
         std::to_string(image.step) + ", " + std::to_string(image.data.size()) + " bytes";
}

// Throws std::invalid_argument unless the declared sizes describe exactly the bytes the
// message carries. Every product is taken in 64 bits: cv_bridge checks height * step ==
// data.size() in 32 bits, where 21846 * 196608 = 2^32 + 131072 passes for 131072 bytes and
// the conversion then reads 4 GiB.
void check_layout(const sensor_msgs::Image& image, const std::string& what, PixelLayout layout) {
  const std::uint64_t width = image.width;
  const std::uint64_t height = image.height;
  const std::uint64_t step = image.step;
  const auto refuse = [&](const std::string& why) {
    throw std::invalid_argument(what + " (" + size_text(image) + "): " + why);
  };
  if (width == 0 || height == 0) refuse("the image is empty");
  if (width > kMaxImageSide || height > kMaxImageSide)
    refuse("a side is longer than " + std::to_string(kMaxImageSide) + " pixels");
  if (step < width * layout.pixel_bytes)
    refuse("the step is shorter than a row of " + std::to_string(width) + " pixels of " +
           std::to_string(layout.pixel_bytes) + " bytes");
  if (step % layout.channel_bytes != 0)
    refuse("the step is not a multiple of a channel's " + std::to_string(layout.channel_bytes) +
           " bytes");
  if (height * step != image.data.size())
    refuse("height * step is " + std::to_string(height * step) + " bytes, not the " +
           std::to_string(image.data.size()) + " the message carries");
}

// A conversion's own failure as a refusal of the frame; running out of memory stays what it
// is (std::bad_alloc), so that the program reports it as such.
template <class Convert>
cv::Mat converted(const std::string& what, Convert convert) {
  try {
    return convert();
  } catch (const cv_bridge::Exception& e) {
    throw std::invalid_argument(what + ": " + e.what());
  } catch (const cv::Exception& e) {
    if (is_out_of_memory(e)) throw std::bad_alloc();
    throw std::invalid_argument(what + ": OpenCV refused it (" + e.err + ")");
  }
}

cv::Mat colour_as_bgr(const sensor_msgs::Image& colour) {
  const std::string& encoding = colour.encoding;
  const std::string what = "colour image";
  if (encoding == encodings::BGR8 || encoding == encodings::RGB8)
    check_layout(colour, what, {3, 1});
  else if (encoding == encodings::BGRA8 || encoding == encodings::RGBA8)
    check_layout(colour, what, {4, 1});
  else
    throw std::invalid_argument("colour image: encoding \"" + text::printable_excerpt(encoding) +
                                "\" is not one of bgr8, rgb8, bgra8, rgba8");
  return converted(what, [&] { return cv_bridge::toCvCopy(colour, encodings::BGR8)->image; });
}

// Metres (32FC1) as millimetres (16UC1).
cv::Mat millimetres_of(const cv::Mat& metres) {
  cv::Mat millimetres(metres.size(), CV_16UC1);
  for (int row = 0; row < metres.rows; ++row) {
    const float* in = metres.ptr<float>(row);
    std::uint16_t* out = millimetres.ptr<std::uint16_t>(row);
    for (int col = 0; col < metres.cols; ++col) {
      const double mm = static_cast<double>(in[col]) * 1000.0;
      // NaN, infinite, negative or beyond 65.5 m: no depth, as the RealSense writes 0.
      out[col] = std::isfinite(mm) && mm > 0.0 && mm < 65535.0
                     ? static_cast<std::uint16_t>(std::lround(mm))
                     : 0;
    }
  }
  return millimetres;
}

// The depth image's pixels as `type` (CV_16UC1 or CV_32FC1, its layout already checked), in
// this machine's byte order. Read here, not by cv_bridge: its byte swap of a big-endian image
// returns the pixels as CV_8UC2 (or CV_8UC4), not as the declared type.
cv::Mat depth_pixels(const sensor_msgs::Image& depth, int type) {
  const cv::Mat view(static_cast<int>(depth.height), static_cast<int>(depth.width), type,
                     const_cast<std::uint8_t*>(depth.data.data()), depth.step);
  cv::Mat pixels = view.clone();
  const bool native_big_endian = __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__;
  if ((depth.is_bigendian != 0) == native_big_endian) return pixels;
  const std::size_t size = pixels.elemSize();
  for (int row = 0; row < pixels.rows; ++row) {
    std::uint8_t* bytes = pixels.ptr<std::uint8_t>(row);
    for (int col = 0; col < pixels.cols; ++col)
      std::reverse(bytes + col * size, bytes + (col + 1) * size);
  }
  return pixels;
}

// Depth in millimetres, 0 where there is none, as perception reads it (depth_scale 0.001).
cv::Mat depth_in_millimetres(const sensor_msgs::Image& depth) {
  const std::string what = "depth image";
  if (depth.encoding == encodings::TYPE_16UC1 || depth.encoding == encodings::MONO16) {
    check_layout(depth, what, {2, 2});
    return converted(what, [&] { return depth_pixels(depth, CV_16UC1); });
  }
  if (depth.encoding == encodings::TYPE_32FC1) {
    check_layout(depth, what, {4, 4});
    return converted(what, [&] { return millimetres_of(depth_pixels(depth, CV_32FC1)); });
  }
  throw std::invalid_argument("depth image: encoding \"" + text::printable_excerpt(depth.encoding) +
                              "\" is not 16UC1 (millimetres) or 32FC1 (metres)");
}

CameraIntrinsics intrinsics_of(const sensor_msgs::CameraInfo& info, const cv::Size& image) {
  const auto& k = info.K;  // row-major 3x3: fx 0 cx / 0 fy cy / 0 0 1
  if (!(k[0] > 0.0) || !(k[4] > 0.0) || !std::isfinite(k[0]) || !std::isfinite(k[4]))
    throw std::invalid_argument("camera_info: K has no focal lengths (fx, fy must be finite, > 0)");
  if (!std::isfinite(k[2]) || !std::isfinite(k[5]))
    throw std::invalid_argument("camera_info: K's principal point (cx, cy) is not finite");
  // Compared as unsigned 64-bit numbers: a width of 2^32 - 1 is not -1.
  const auto width = static_cast<std::uint64_t>(image.width);
  const auto height = static_cast<std::uint64_t>(image.height);
  if (info.width != 0 && (info.width != width || info.height != height))
    throw std::invalid_argument("camera_info: " + std::to_string(info.width) + "x" +
                                std::to_string(info.height) + " but the images are " +
                                std::to_string(image.width) + "x" + std::to_string(image.height));
  CameraIntrinsics intrinsics;
  intrinsics.fx = k[0];
  intrinsics.fy = k[4];
  intrinsics.cx = k[2];
  intrinsics.cy = k[5];
  intrinsics.width = image.width;
  intrinsics.height = image.height;
  return intrinsics;
}

double yaw_of(const geometry_msgs::Quaternion& q) {
  return std::atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z));
}

geometry_msgs::Quaternion quaternion_of_yaw(double yaw) {
  geometry_msgs::Quaternion q;
  q.z = std::sin(yaw / 2.0);
  q.w = std::cos(yaw / 2.0);
  return q;
}

}  // namespace

Frame frame_from_messages(const sensor_msgs::Image& colour, const sensor_msgs::Image& depth,
                          const sensor_msgs::CameraInfo& info) {
  Frame frame;
  frame.colour = colour_as_bgr(colour);
  frame.depth = depth_in_millimetres(depth);
  if (frame.colour.size() != frame.depth.size())
    throw std::invalid_argument(
        "the depth image (" + std::to_string(frame.depth.cols) + "x" +
        std::to_string(frame.depth.rows) + ") is not registered to the colour image (" +
        std::to_string(frame.colour.cols) + "x" + std::to_string(frame.colour.rows) +
        "): use the depth topic aligned to colour");
  frame.depth_scale_m_per_unit = 0.001;
  frame.intrinsics = intrinsics_of(info, frame.colour.size());
  frame.timestamp_s = colour.header.stamp.toSec();
  return frame;
}

CameraMessages messages_from_frame(const Frame& frame, const ros::Time& stamp,
                                   const std::string& optical_frame) {
  if (frame.depth_scale_m_per_unit != 0.001)
    throw std::invalid_argument("messages_from_frame: depth must be in millimetres");
  std_msgs::Header header;
  header.stamp = stamp;
  header.frame_id = optical_frame;
  CameraMessages messages;
  cv_bridge::CvImage(header, encodings::BGR8, frame.colour).toImageMsg(messages.colour);
  cv_bridge::CvImage(header, encodings::TYPE_16UC1, frame.depth).toImageMsg(messages.depth);
  const CameraIntrinsics& k = frame.intrinsics;
  messages.info.header = header;
  messages.info.width = static_cast<std::uint32_t>(frame.colour.cols);
  messages.info.height = static_cast<std::uint32_t>(frame.colour.rows);
  messages.info.distortion_model = "plumb_bob";
  messages.info.D = {0.0, 0.0, 0.0, 0.0, 0.0};
  messages.info.K = {k.fx, 0.0, k.cx, 0.0, k.fy, k.cy, 0.0, 0.0, 1.0};
  messages.info.R = {1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0};
  messages.info.P = {k.fx, 0.0, k.cx, 0.0, 0.0, k.fy, k.cy, 0.0, 0.0, 0.0, 1.0, 0.0};
  return messages;
}

go1::Pose pose_from_odometry(const nav_msgs::Odometry& odometry) {
  const auto& pose = odometry.pose.pose;
  return {pose.position.x, pose.position.y, yaw_of(pose.orientation)};
}

nav_msgs::Odometry odometry_from_pose(const go1::Pose& pose, const go1::VelocityCommand& velocity,
                                      const ros::Time& stamp, const std::string& odom_frame,
                                      const std::string& base_frame) {
  nav_msgs::Odometry odometry;
  odometry.header.stamp = stamp;
  odometry.header.frame_id = odom_frame;
  odometry.child_frame_id = base_frame;
  odometry.pose.pose.position.x = pose.x;
  odometry.pose.pose.position.y = pose.y;
  odometry.pose.pose.orientation = quaternion_of_yaw(pose.yaw);
  odometry.twist.twist = twist_from_velocity(velocity);  // REP-105: in the child frame
  return odometry;
}

geometry_msgs::Twist twist_from_velocity(const go1::VelocityCommand& velocity) {
  geometry_msgs::Twist twist;
  twist.linear.x = velocity.forward;
  twist.linear.y = velocity.lateral;
  twist.angular.z = velocity.yaw_rate;
  return twist;
}

go1::VelocityCommand velocity_from_twist(const geometry_msgs::Twist& twist) {
  return {static_cast<float>(twist.linear.x), static_cast<float>(twist.linear.y),
          static_cast<float>(twist.angular.z)};
}

PerceptionResult perception_from_detections(const Detections& detections) {
  const auto& poses = detections.positions.poses;
  if (poses.size() != 2)
    throw std::invalid_argument(
        "detections: expected one pose per catalog object (2: human 1, "
        "human 2), got " +
        std::to_string(poses.size()));
  PerceptionResult seen;
  for (std::size_t k = 0; k < 2; ++k) {
    const auto& position = poses[k].position;
    HumanEstimate& human = seen.humans[k];
    human.seen = std::isfinite(position.x) && std::isfinite(position.y);
    if (!human.seen) continue;
    human.x_m = position.x;
    human.y_m = position.y;
    human.confidence = 1.0;
    human.depth_m = position.x;
  }
  const int holder = detections.holder.value_or(0);
  if (holder < 0 || holder > 2)
    throw std::invalid_argument("treat_holder: expected 0 (nobody), 1 or 2, got " +
                                std::to_string(holder));
  seen.holder = static_cast<TreatHolder>(holder);
  const double reward = detections.reward.value_or(0.0);
  seen.reward_known = std::isfinite(reward);
  seen.reward = seen.reward_known ? reward : 0.0;
  return seen;
}

Detections detections_from_perception(const PerceptionResult& seen, const ros::Time& stamp,
                                      const std::string& base_frame) {
  Detections detections;
  detections.positions.header.stamp = stamp;
  detections.positions.header.frame_id = base_frame;
  for (const HumanEstimate& human : seen.humans) {
    geometry_msgs::Pose pose;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    pose.position.x = human.seen ? human.x_m : nan;
    pose.position.y = human.seen ? human.y_m : nan;
    pose.orientation.w = 1.0;
    detections.positions.poses.push_back(pose);
  }
  detections.reward = seen.reward_known ? seen.reward : std::numeric_limits<double>::quiet_NaN();
  detections.holder = static_cast<int>(seen.holder);
  return detections;
}

diagnostic_msgs::DiagnosticArray truth_message(const std::string& context_name, double reward,
                                               const ros::Time& stamp) {
  diagnostic_msgs::DiagnosticArray message;
  message.header.stamp = stamp;
  diagnostic_msgs::DiagnosticStatus status;
  status.level = diagnostic_msgs::DiagnosticStatus::OK;
  status.name = kTruthStatusName;
  status.message = context_name;
  diagnostic_msgs::KeyValue context;
  context.key = "context";
  context.value = context_name;
  diagnostic_msgs::KeyValue reward_value;
  reward_value.key = "reward";
  reward_value.value = reward > 0.5 ? "1" : "0";
  status.values = {context, reward_value};
  message.status.push_back(status);
  return message;
}

std::optional<log::GroundTruth> truth_from_message(const diagnostic_msgs::DiagnosticArray& message,
                                                   const std::vector<std::string>& context_names) {
  for (const diagnostic_msgs::DiagnosticStatus& status : message.status) {
    if (status.name != kTruthStatusName) continue;
    std::optional<std::uint32_t> context;
    std::optional<double> reward;
    for (const diagnostic_msgs::KeyValue& value : status.values) {
      if (value.key == "reward" && (value.value == "0" || value.value == "1"))
        reward = value.value == "1" ? 1.0 : 0.0;
      if (value.key != "context") continue;
      for (std::size_t k = 0; k < context_names.size(); ++k)
        if (context_names[k] == value.value) context = static_cast<std::uint32_t>(k);
    }
    if (context && reward) return log::GroundTruth{*context, *reward};
  }
  return std::nullopt;
}

}  // namespace oasis::hw::ros_node
