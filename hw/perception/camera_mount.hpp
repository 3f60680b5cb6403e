// Where the camera sits on the robot, and the change of frame between the camera's optical
// frame (x right, y down, z forward) and the robot frame (x forward, y left, z up, origin on
// the ground below the camera). The camera looks along +x, pitched up so that a standing
// person's shirt stays in view from 0.5 m to 4 m.
#pragma once

#include "perception/frame.hpp"

namespace oasis::hw {

struct CameraMount {
  double height_m = 0.5;         // optical centre above the ground
  double pitch_up_rad = 0.4363;  // 25 degrees: at 0.5 m the view still reaches 1.29 m up
};

struct Point3 {
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;
};

// A direction (no translation) from the optical frame into the robot frame.
Point3 robot_direction_from_camera(const CameraMount& mount, const Point3& camera);

Point3 robot_point_from_camera(const CameraMount& mount, const Point3& camera);
Point3 camera_point_from_robot(const CameraMount& mount, const Point3& robot);

// Does the robot-frame point project into the image, at least margin_px inside its border (and in
// front of the camera)?
bool projects_inside_image(const CameraIntrinsics& intrinsics, const CameraMount& mount,
                           const Point3& robot, double margin_px);

// The robot-frame point seen at pixel (u, v) with z-depth depth_m.
Point3 back_project(const CameraIntrinsics& intrinsics, const CameraMount& mount, double u,
                    double v, double depth_m);

}  // namespace oasis::hw
