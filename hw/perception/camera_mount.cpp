#include "perception/camera_mount.hpp"

#include <cmath>

namespace oasis::hw {

Point3 robot_direction_from_camera(const CameraMount& mount, const Point3& camera) {
  const double c = std::cos(mount.pitch_up_rad);
  const double s = std::sin(mount.pitch_up_rad);
  // Optical z is (c, 0, s) in the robot frame, optical y (down) is (s, 0, -c), optical x is -y.
  return {camera.z * c + camera.y * s, -camera.x, camera.z * s - camera.y * c};
}

Point3 robot_point_from_camera(const CameraMount& mount, const Point3& camera) {
  Point3 robot = robot_direction_from_camera(mount, camera);
  robot.z += mount.height_m;
  return robot;
}

Point3 camera_point_from_robot(const CameraMount& mount, const Point3& robot) {
  const double c = std::cos(mount.pitch_up_rad);
  const double s = std::sin(mount.pitch_up_rad);
  const double up = robot.z - mount.height_m;
  return {-robot.y, robot.x * s - up * c, robot.x * c + up * s};
}

bool projects_inside_image(const CameraIntrinsics& intrinsics, const CameraMount& mount,
                           const Point3& robot, double margin_px) {
  const Point3 camera = camera_point_from_robot(mount, robot);
  if (camera.z <= 0.0) return false;  // behind the image plane
  const double u = intrinsics.fx * camera.x / camera.z + intrinsics.cx;
  const double v = intrinsics.fy * camera.y / camera.z + intrinsics.cy;
  return u >= margin_px && u <= intrinsics.width - 1 - margin_px && v >= margin_px &&
         v <= intrinsics.height - 1 - margin_px;
}

Point3 back_project(const CameraIntrinsics& intrinsics, const CameraMount& mount, double u,
                    double v, double depth_m) {
  const Point3 camera{(u - intrinsics.cx) / intrinsics.fx * depth_m,
                      (v - intrinsics.cy) / intrinsics.fy * depth_m, depth_m};
  return robot_point_from_camera(mount, camera);
}

}  // namespace oasis::hw
