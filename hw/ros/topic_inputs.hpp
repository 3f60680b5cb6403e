#pragma once
// Where oasis-ros's observations come from: the camera's topics (colour, depth and CameraInfo,
// matched by stamp) or a tracker's detections, each with the robot's odometry and, from a
// simulator or a bag recorded with one, the ground truth of the same instant. ROS-free header.
#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "go1/planar_pose.hpp"
#include "log/step_record.hpp"
#include "perception/frame.hpp"
#include "perception/perception_result.hpp"
#include "ros/input_topics.hpp"
#include "ros/ros_session.hpp"

namespace oasis::hw::ros_node {

// One observation, and what came with it.
struct ObservedInput {
  double stamp_s = 0.0;                        // the message's header stamp
  std::uint64_t stamp_ns = 0;                  // the same, exactly: the key across topics
  std::optional<Frame> frame;                  // camera mode
  std::optional<PerceptionResult> detections;  // detections mode (tag visibility not marked)
  std::optional<go1::Pose> odometry;           // the robot's pose at the stamp, if known
  std::optional<log::GroundTruth> truth;       // when a ground-truth topic speaks
};

// A source of observations: live topics (TopicInputs) or a recording.
class InputFeed {
 public:
  virtual ~InputFeed() = default;
  // The next observation, waiting at most `timeout`; nothing when none came in time (or the
  // feed ended).
  virtual std::optional<ObservedInput> next(std::chrono::milliseconds timeout) = 0;
  // True once a recording has given its last observation; live topics never end.
  virtual bool ended() const { return false; }
  virtual std::string describe() const = 0;
};

struct TopicInputOptions {
  InputMode mode = InputMode::kCamera;
  RosTopics topics;
  bool use_odom = true;
  std::vector<std::string> context_names;  // to read the ground truth's context
};

class TopicInputs final : public InputFeed {
 public:
  // Subscribes at once; observations queue (the newest only) until next() takes them.
  TopicInputs(RosSession& session, TopicInputOptions options);
  ~TopicInputs() override;

  std::optional<ObservedInput> next(std::chrono::milliseconds timeout) override;
  std::string describe() const override;

  // Observations replaced by a newer one before the loop took them (the loop fell behind).
  std::uint64_t dropped() const;
  // Messages that could not be read (an encoding we do not take, sizes that do not describe
  // the bytes carried, images that differ in size; message_conversion.hpp), and why the last
  // one could not.
  std::uint64_t refused() const;
  std::string last_refusal() const;

  struct State;  // topic_inputs.cpp

 private:
  std::unique_ptr<State> state_;
};

}  // namespace oasis::hw::ros_node
