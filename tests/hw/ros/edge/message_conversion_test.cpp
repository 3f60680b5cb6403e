// The conversion of camera messages into a Frame (hw/ros/message_conversion.hpp) on the frames
// of issue 37: sizes whose 32-bit products wrap around to the bytes carried, an empty frame,
// steps OpenCV cannot take, camera info beyond int. Each is refused with std::invalid_argument
// (counted by the node as a malformed frame), never read past its bytes, never a cv::Exception.
//
// Compiles as C++17, like the edge it tests (ROS 1's message headers).
#include "ros/message_conversion.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

namespace oasis::hw::ros_node {
namespace {

sensor_msgs::Image image(const std::string& encoding, std::uint32_t width, std::uint32_t height,
                         std::uint32_t step, std::size_t bytes) {
  sensor_msgs::Image message;
  message.encoding = encoding;
  message.width = width;
  message.height = height;
  message.step = step;
  message.data.assign(bytes, 0x40);
  return message;
}

// A well-formed colour, depth and camera info of `width` x `height`.
struct Camera {
  sensor_msgs::Image colour;
  sensor_msgs::Image depth;
  sensor_msgs::CameraInfo info;
};

Camera camera(std::uint32_t width, std::uint32_t height) {
  Camera c;
  c.colour = image("bgr8", width, height, width * 3, std::size_t{width} * height * 3);
  c.depth = image("16UC1", width, height, width * 2, std::size_t{width} * height * 2);
  c.info.width = width;
  c.info.height = height;
  c.info.K = {500.0, 0.0, width / 2.0, 0.0, 500.0, height / 2.0, 0.0, 0.0, 1.0};
  return c;
}

// The text of the refusal; fails the test when the frame is accepted or something else is
// thrown.
std::string refusal(const Camera& c) {
  try {
    frame_from_messages(c.colour, c.depth, c.info);
  } catch (const std::invalid_argument& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "not a refusal: " << e.what();
    return "";
  }
  ADD_FAILURE() << "the frame was accepted";
  return "";
}

TEST(MessageConversion, a_well_formed_frame_has_the_declared_sizes) {
  const Camera c = camera(4, 3);
  const Frame frame = frame_from_messages(c.colour, c.depth, c.info);
  EXPECT_EQ(frame.colour.cols, 4);
  EXPECT_EQ(frame.colour.rows, 3);
  EXPECT_EQ(frame.colour.type(), CV_8UC3);
  EXPECT_EQ(frame.depth.cols, 4);
  EXPECT_EQ(frame.depth.rows, 3);
  EXPECT_EQ(frame.depth.type(), CV_16UC1);
  EXPECT_EQ(frame.intrinsics.width, 4);
  EXPECT_EQ(frame.intrinsics.height, 3);
}

TEST(MessageConversion, a_one_pixel_frame_and_padded_rows_are_taken) {
  Camera c = camera(1, 1);
  EXPECT_NO_THROW(frame_from_messages(c.colour, c.depth, c.info));
  c = camera(5, 2);
  c.colour = image("rgba8", 5, 2, 24, 48);  // 20 bytes a row, 4 of padding
  c.depth = image("32FC1", 5, 2, 24, 48);   // 20 bytes a row, one float of padding
  const Frame frame = frame_from_messages(c.colour, c.depth, c.info);
  EXPECT_EQ(frame.colour.size(), cv::Size(5, 2));
  EXPECT_EQ(frame.depth.size(), cv::Size(5, 2));
}

// 21846 * 196608 = 2^32 + 131072: a 32-bit check of height * step against the 131072 bytes
// passes, and the conversion read 4 GiB (issue 37, item 1).
TEST(MessageConversion, height_times_step_is_taken_in_64_bits) {
  Camera c = camera(4, 4);
  c.colour = image("bgr8", 65536, 21846, 196608, 131072);
  EXPECT_NE(refusal(c).find("height * step is 4295098368 bytes, not the 131072"), std::string::npos)
      << refusal(c);
  // Height 65537: a 12.9 GB allocation, which OpenCV threw as cv::Exception.
  c.colour = image("bgr8", 65536, 65537, 196608, 131072);
  EXPECT_NE(refusal(c).find("a side is longer than 65536"), std::string::npos) << refusal(c);
}

TEST(MessageConversion, depth_sizes_are_taken_in_64_bits) {
  Camera c = camera(4, 4);
  c.depth = image("16UC1", 65536, 32769, 131072, 131072);  // 32769 * 131072 = 2^32 + 131072
  EXPECT_NE(refusal(c).find("depth image"), std::string::npos);
  c.depth = image("32FC1", 65536, 16385, 262144, 262144);  // 16385 * 262144 = 2^32 + 262144
  EXPECT_NE(refusal(c).find("depth image"), std::string::npos);
}

TEST(MessageConversion, an_empty_frame_is_refused) {
  Camera c = camera(4, 4);
  c.colour = image("bgr8", 0, 0, 0, 0);
  c.depth = image("16UC1", 0, 0, 0, 0);
  c.info.width = c.info.height = 0;
  EXPECT_NE(refusal(c).find("the image is empty"), std::string::npos);
  c = camera(4, 4);
  c.depth = image("16UC1", 4, 0, 8, 0);
  EXPECT_NE(refusal(c).find("depth image"), std::string::npos);
}

// width * 3 = 2^32 + 2 in 32 bits is 2: cv_bridge's own row check passes a step of 2.
TEST(MessageConversion, a_row_longer_than_the_step_is_refused) {
  Camera c = camera(4, 4);
  c.colour = image("bgr8", 4, 4, 11, 44);
  EXPECT_NE(refusal(c).find("the step is shorter than a row"), std::string::npos);
  c.colour = image("bgr8", 0x55555556u, 1, 2, 2);
  EXPECT_NE(refusal(c).find("colour image"), std::string::npos);
}

// OpenCV takes a step only in whole channels; it threw a cv::Exception for an odd step.
TEST(MessageConversion, a_step_of_part_of_a_channel_is_refused) {
  Camera c = camera(4, 4);
  c.depth = image("16UC1", 4, 4, 9, 36);
  EXPECT_NE(refusal(c).find("not a multiple of a channel's 2 bytes"), std::string::npos);
  c.depth = image("32FC1", 4, 4, 18, 72);
  EXPECT_NE(refusal(c).find("not a multiple of a channel's 4 bytes"), std::string::npos);
}

// Found by the ros_messages fuzz target: cv_bridge returned a big-endian 16UC1 image as
// CV_8UC2. The depth is read here, swapped to this machine's order, as the declared type.
TEST(MessageConversion, big_endian_depth_keeps_its_type_and_values) {
  Camera c = camera(2, 1);
  c.depth = image("16UC1", 2, 1, 4, 4);
  c.depth.is_bigendian = 1;
  c.depth.data = {0x01, 0x02, 0x00, 0x10};  // 258 mm, 16 mm
  Frame frame = frame_from_messages(c.colour, c.depth, c.info);
  ASSERT_EQ(frame.depth.type(), CV_16UC1);
  EXPECT_EQ(frame.depth.at<std::uint16_t>(0, 0), 258);
  EXPECT_EQ(frame.depth.at<std::uint16_t>(0, 1), 16);
  c.depth = image("32FC1", 2, 1, 8, 8);
  c.depth.is_bigendian = 1;
  c.depth.data = {0x3f, 0xc0, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00};  // 1.5 m, 0 (no depth)
  frame = frame_from_messages(c.colour, c.depth, c.info);
  ASSERT_EQ(frame.depth.type(), CV_16UC1);
  EXPECT_EQ(frame.depth.at<std::uint16_t>(0, 0), 1500);
  EXPECT_EQ(frame.depth.at<std::uint16_t>(0, 1), 0);
}

TEST(MessageConversion, encodings_we_do_not_take_are_named) {
  Camera c = camera(4, 4);
  c.colour.encoding = "mono8";
  EXPECT_NE(refusal(c).find("\"mono8\""), std::string::npos);
  c = camera(4, 4);
  c.depth.encoding = "8UC1";
  EXPECT_NE(refusal(c).find("\"8UC1\""), std::string::npos);
}

TEST(MessageConversion, camera_info_is_compared_without_wrapping_around) {
  Camera c = camera(4, 4);
  c.info.width = std::numeric_limits<std::uint32_t>::max();  // -1 as an int
  EXPECT_NE(refusal(c).find("camera_info"), std::string::npos);
  c = camera(4, 4);
  c.info.K[0] = std::numeric_limits<double>::infinity();
  EXPECT_NE(refusal(c).find("focal lengths"), std::string::npos);
  c = camera(4, 4);
  c.info.K[2] = std::nan("");
  EXPECT_NE(refusal(c).find("principal point"), std::string::npos);
}

TEST(MessageConversion, images_of_different_sizes_are_refused) {
  Camera c = camera(4, 4);
  c.depth = image("16UC1", 4, 3, 8, 24);
  EXPECT_NE(refusal(c).find("not registered"), std::string::npos);
}

TEST(MessageConversion, detections_need_one_pose_per_object_and_a_holder_in_range) {
  Detections detections;
  EXPECT_THROW(perception_from_detections(detections), std::invalid_argument);
  detections.positions.poses.resize(2);
  detections.holder = 3;
  EXPECT_THROW(perception_from_detections(detections), std::invalid_argument);
  detections.holder = 1;
  detections.positions.poses[0].position.x = std::numeric_limits<double>::infinity();
  const PerceptionResult seen = perception_from_detections(detections);
  EXPECT_FALSE(seen.humans[0].seen);
  EXPECT_TRUE(seen.humans[1].seen);
}

}  // namespace
}  // namespace oasis::hw::ros_node
