// The frame change between the camera's optical frame and the robot frame, and projection.
#include "perception/camera_mount.hpp"

#include <gtest/gtest.h>

namespace oasis::hw {
namespace {

TEST(CameraMount, RobotAndCameraFramesAreInverse) {
  const CameraMount mount{0.5, 0.3};
  const Point3 robot{2.0, -0.7, 1.1};
  const Point3 back = robot_point_from_camera(mount, camera_point_from_robot(mount, robot));
  EXPECT_NEAR(back.x, robot.x, 1e-12);
  EXPECT_NEAR(back.y, robot.y, 1e-12);
  EXPECT_NEAR(back.z, robot.z, 1e-12);
}

TEST(CameraMount, LevelCameraLooksAlongForwardWithLeftOnTheImageLeft) {
  const CameraMount level{0.4, 0.0};
  const CameraIntrinsics k;
  const Point3 centre = back_project(k, level, k.cx, k.cy, 3.0);
  EXPECT_NEAR(centre.x, 3.0, 1e-12);
  EXPECT_NEAR(centre.y, 0.0, 1e-12);
  EXPECT_NEAR(centre.z, 0.4, 1e-12);
  const Point3 left = back_project(k, level, k.cx - k.fx, k.cy, 3.0);  // 45 deg left
  EXPECT_NEAR(left.y, 3.0, 1e-12);
}

TEST(CameraMount, PitchedCameraSeesHigherAtTheImageTop) {
  const CameraMount mount;  // default: pitched up
  const CameraIntrinsics k;
  const Point3 top = back_project(k, mount, k.cx, 0.0, 2.0);
  const Point3 bottom = back_project(k, mount, k.cx, k.height - 1.0, 2.0);
  EXPECT_GT(top.z, bottom.z);
}

}  // namespace
}  // namespace oasis::hw
