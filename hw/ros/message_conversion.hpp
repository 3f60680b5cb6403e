#pragma once
// Between ROS messages and the loop's own types, both ways: the node reads with one direction,
// the hallway simulator node and the tests write with the other, so each pair is one place.
// Units and frames follow REP-103 (metres, radians, x forward, y left, z up; a camera's optical
// frame x right, y down, z forward) and REP-105 (odom, base_link).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <diagnostic_msgs/DiagnosticArray.h>
#include <geometry_msgs/PoseArray.h>
#include <geometry_msgs/Twist.h>
#include <nav_msgs/Odometry.h>
#include <ros/time.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>

#include "go1/motion_limits.hpp"
#include "go1/planar_pose.hpp"
#include "log/step_record.hpp"
#include "perception/frame.hpp"
#include "perception/perception_result.hpp"

namespace oasis::hw::ros_node {

// ---- camera ----

// A Frame from a colour image (bgr8, rgb8, bgra8 or rgba8), a depth image registered to it
// (16UC1 in millimetres, or 32FC1 in metres, NaN or 0 for no depth) and the colour camera's
// CameraInfo (K gives fx, fy, cx, cy). The frame's time is the colour image's stamp. Throws
// std::invalid_argument naming what does not fit: an encoding, an empty image, a side over
// 65536 pixels, a step shorter than a row or not whole channels, height * step other than the
// bytes carried (all in 64 bits), sizes that differ, a K without finite fx, fy > 0, cx, cy.
// An accepted frame is exactly the declared width x height (CV_8UC3 colour, CV_16UC1 depth).
// Throws std::bad_alloc when memory runs out; nothing else.
Frame frame_from_messages(const sensor_msgs::Image& colour, const sensor_msgs::Image& depth,
                          const sensor_msgs::CameraInfo& info);

struct CameraMessages {
  sensor_msgs::Image colour;  // bgr8
  sensor_msgs::Image depth;   // 16UC1, millimetres (the frame's depth scale must be 0.001)
  sensor_msgs::CameraInfo info;
};

// The messages a camera driver would publish for `frame`, stamped `stamp` in `optical_frame`.
CameraMessages messages_from_frame(const Frame& frame, const ros::Time& stamp,
                                   const std::string& optical_frame);

// ---- the robot ----

// The planar pose in an Odometry message: position x, y and the yaw of its orientation.
go1::Pose pose_from_odometry(const nav_msgs::Odometry& odometry);

// An Odometry message for a planar pose and body velocity (z = 0, roll = pitch = 0).
nav_msgs::Odometry odometry_from_pose(const go1::Pose& pose, const go1::VelocityCommand& velocity,
                                      const ros::Time& stamp, const std::string& odom_frame,
                                      const std::string& base_frame);

// linear.x forward, linear.y left, angular.z counter-clockwise; the rest 0.
geometry_msgs::Twist twist_from_velocity(const go1::VelocityCommand& velocity);
go1::VelocityCommand velocity_from_twist(const geometry_msgs::Twist& twist);

// ---- detections mode ----

// What a robot's own tracker reports in one message: pose k is object k of the catalog (for the
// Go1 spec: human 1, then human 2) in the base frame; an object not seen has a NaN x. The reward
// and the treat's holder come on their own topics (std_msgs/Float64, NaN for "not known";
// std_msgs/Int8, 0 nobody, 1 or 2), the latest of each counting.
struct Detections {
  geometry_msgs::PoseArray positions;
  std::optional<double> reward;  // nothing: no reward topic has spoken yet
  std::optional<int> holder;
};

// The perception result the controller is given for them. Throws std::invalid_argument when
// there is not exactly one pose per object (2), or the holder is not 0, 1 or 2.
PerceptionResult perception_from_detections(const Detections& detections);

// The detections a tracker would report when it sees what `seen` says: the inverse of the above
// for the fields it carries (positions, who was seen, the reward, its being known, the holder).
Detections detections_from_perception(const PerceptionResult& seen, const ros::Time& stamp,
                                      const std::string& base_frame);

// ---- ground truth (a simulator, or a bag recorded with it) ----

// One status named "oasis ground truth" with the keys context (a catalog context's name) and
// reward (0 or 1), stamped like the frame it describes.
diagnostic_msgs::DiagnosticArray truth_message(const std::string& context_name, double reward,
                                               const ros::Time& stamp);

// The truth in such a message, the context by its index in `context_names`; nothing when the
// message is not one, or names no such context.
std::optional<log::GroundTruth> truth_from_message(const diagnostic_msgs::DiagnosticArray& message,
                                                   const std::vector<std::string>& context_names);

}  // namespace oasis::hw::ros_node
