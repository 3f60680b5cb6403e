// The synthetic renderer: depth agrees with the ground truth, the tag is libapriltag's own,
// noise is deterministic per seed and grows with distance, and the source ends cleanly.
#include "perception/synthetic_renderer.hpp"

#include <cmath>
#include <variant>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include "perception/camera_mount.hpp"
#include "perception/tag_bitmap.hpp"

namespace oasis::hw {
namespace {

SyntheticScene one_person_at(double x_m, double y_m) {
  SyntheticScene scene;
  scene.people[0] = PersonPlacement{x_m, y_m};
  return scene;
}

// The pixel where the robot-frame point appears.
cv::Point pixel_of(const RenderSettings& settings, const Point3& robot) {
  const Point3 camera = camera_point_from_robot(settings.mount, robot);
  const CameraIntrinsics& k = settings.intrinsics;
  return {static_cast<int>(std::lround(k.fx * camera.x / camera.z + k.cx)),
          static_cast<int>(std::lround(k.fy * camera.y / camera.z + k.cy))};
}

TEST(SyntheticRenderer, FrameHasTheStatedFormat) {
  const RenderSettings settings;
  const Frame frame = render_scene(one_person_at(2.0, 0.0), settings, 1.5);
  EXPECT_EQ(frame.colour.type(), CV_8UC3);
  EXPECT_EQ(frame.depth.type(), CV_16UC1);
  EXPECT_EQ(frame.colour.cols, 640);
  EXPECT_EQ(frame.colour.rows, 480);
  EXPECT_EQ(frame.depth.size(), frame.colour.size());
  EXPECT_DOUBLE_EQ(frame.timestamp_s, 1.5);
}

TEST(SyntheticRenderer, ShirtPixelHasTheShirtDepthAndColour) {
  RenderSettings settings;
  settings.colour_noise_sigma = 0;
  const Frame frame = render_scene(one_person_at(2.0, 0.3), settings);
  const Point3 chest{2.0, 0.3, 1.2};
  const cv::Point pixel = pixel_of(settings, chest);
  const double expected_depth_m = camera_point_from_robot(settings.mount, chest).z;
  EXPECT_NEAR(frame.depth.at<std::uint16_t>(pixel) * 0.001, expected_depth_m, 0.002);
  const cv::Vec3b colour = frame.colour.at<cv::Vec3b>(pixel);
  EXPECT_GT(colour[2], 150);  // red
  EXPECT_LT(colour[1], 80);
}

TEST(SyntheticRenderer, TagBitmapIsTheLibraryTag) {
  const cv::Mat bitmap = tag36h11_bitmap(7);
  ASSERT_EQ(bitmap.rows, 10);
  ASSERT_EQ(bitmap.cols, 10);
  EXPECT_EQ(bitmap.at<std::uint8_t>(0, 0), 255);  // white outer ring
  EXPECT_EQ(bitmap.at<std::uint8_t>(1, 1), 0);    // black border
  EXPECT_THROW(tag36h11_bitmap(587), std::out_of_range);
}

TEST(SyntheticRenderer, NoiseIsDeterministicPerSeedAndGrowsWithDistance) {
  RenderSettings settings;
  settings.depth_noise = DepthNoise::realsense_like();
  SyntheticScene scene = one_person_at(1.0, 0.0);
  const Frame first = render_scene(scene, settings);
  const Frame again = render_scene(scene, settings);
  EXPECT_EQ(cv::norm(first.depth, again.depth, cv::NORM_L1), 0.0);
  scene.seed = 2;
  EXPECT_GT(cv::norm(first.depth, render_scene(scene, settings).depth, cv::NORM_L1), 0.0);
  EXPECT_LT(DepthNoise::realsense_like().sigma_at(1.0), DepthNoise::realsense_like().sigma_at(4.0));
}

TEST(SyntheticRenderer, SourcePlaysEverySceneThenEnds) {
  SyntheticFrameSource source({one_person_at(1.0, 0.0), one_person_at(2.0, 0.0)}, RenderSettings{},
                              0.2);
  ASSERT_TRUE(std::holds_alternative<Frame>(source.next()));
  const NextFrame second = source.next();
  ASSERT_TRUE(std::holds_alternative<Frame>(second));
  EXPECT_DOUBLE_EQ(std::get<Frame>(second).timestamp_s, 0.2);
  const NextFrame end = source.next();
  ASSERT_TRUE(std::holds_alternative<SourceStop>(end));
  EXPECT_EQ(std::get<SourceStop>(end).kind, SourceStop::Kind::kEnd);
}

}  // namespace
}  // namespace oasis::hw
