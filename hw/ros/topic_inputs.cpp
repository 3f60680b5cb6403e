#include "ros/topic_inputs.hpp"

#include <condition_variable>
#include <deque>
#include <map>
#include <mutex>
#include <new>
#include <stdexcept>

#include <diagnostic_msgs/DiagnosticArray.h>
#include <geometry_msgs/PoseArray.h>
#include <message_filters/subscriber.h>
#include <message_filters/time_synchronizer.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <std_msgs/Float64.h>
#include <std_msgs/Int8.h>

#include "ros/message_conversion.hpp"
#include "ros/ros_session_handles.hpp"

namespace oasis::hw::ros_node {
namespace {

constexpr std::size_t kKeptOdometry = 200;  // 4 s at 50 Hz
constexpr std::size_t kKeptTruths = 50;
// A simulator publishes the truth of a frame just before the frame; across connections it may
// still arrive just after. The loop waits this long for it, once a truth has ever come.
constexpr std::chrono::milliseconds kTruthWait{100};

using ImageSync = message_filters::TimeSynchronizer<sensor_msgs::Image, sensor_msgs::Image,
                                                    sensor_msgs::CameraInfo>;

}  // namespace

struct TopicInputs::State {
  TopicInputOptions options;
  mutable std::mutex mutex;
  std::condition_variable arrived;
  std::optional<ObservedInput> pending;
  std::deque<std::pair<ros::Time, go1::Pose>> odometry;  // oldest first
  std::map<std::uint64_t, log::GroundTruth> truths;      // by stamp, in nanoseconds
  bool truth_seen = false;
  std::optional<double> reward;
  std::optional<int> holder;
  std::uint64_t dropped = 0;
  std::uint64_t refused = 0;
  std::string last_refusal;

  // ROS objects last: they stop calling back before the rest goes.
  std::unique_ptr<message_filters::Subscriber<sensor_msgs::Image>> colour;
  std::unique_ptr<message_filters::Subscriber<sensor_msgs::Image>> depth;
  std::unique_ptr<message_filters::Subscriber<sensor_msgs::CameraInfo>> info;
  std::unique_ptr<ImageSync> sync;
  std::vector<ros::Subscriber> subscribers;

  // The pose at `stamp`: the odometry of that stamp, or the latest before it, or the latest.
  std::optional<go1::Pose> pose_at(const ros::Time& stamp) const {
    if (odometry.empty()) return std::nullopt;
    for (auto it = odometry.rbegin(); it != odometry.rend(); ++it)
      if (it->first <= stamp) return it->second;
    return odometry.back().second;
  }

  void offer(ObservedInput input, const ros::Time& stamp) {
    std::lock_guard<std::mutex> lock(mutex);
    if (options.use_odom) input.odometry = pose_at(stamp);
    if (pending) ++dropped;
    pending = std::move(input);
    arrived.notify_one();
  }

  void refuse(const std::string& why) {
    std::lock_guard<std::mutex> lock(mutex);
    ++refused;
    last_refusal = why;
    ROS_WARN_THROTTLE(5.0, "oasis-ros: input refused: %s", why.c_str());
  }

  void on_images(const sensor_msgs::ImageConstPtr& colour_image,
                 const sensor_msgs::ImageConstPtr& depth_image,
                 const sensor_msgs::CameraInfoConstPtr& camera_info) {
    ObservedInput input;
    try {
      input.frame = frame_from_messages(*colour_image, *depth_image, *camera_info);
    } catch (const std::bad_alloc&) {
      // Counted like a malformed frame: no observation, so the fail-safe stops the robot.
      refuse("out of memory while converting the frame");
      return;
    } catch (const std::exception& e) {
      refuse(e.what());
      return;
    }
    input.stamp_s = colour_image->header.stamp.toSec();
    input.stamp_ns = colour_image->header.stamp.toNSec();
    offer(std::move(input), colour_image->header.stamp);
  }

  void on_detections(const geometry_msgs::PoseArrayConstPtr& message) {
    Detections detections;
    detections.positions = *message;
    {
      std::lock_guard<std::mutex> lock(mutex);
      detections.reward = reward;
      detections.holder = holder;
    }
    ObservedInput input;
    try {
      input.detections = perception_from_detections(detections);
    } catch (const std::exception& e) {
      refuse(e.what());
      return;
    }
    input.stamp_s = message->header.stamp.toSec();
    input.stamp_ns = message->header.stamp.toNSec();
    offer(std::move(input), message->header.stamp);
  }

  void on_odometry(const nav_msgs::OdometryConstPtr& message) {
    std::lock_guard<std::mutex> lock(mutex);
    odometry.emplace_back(message->header.stamp, pose_from_odometry(*message));
    if (odometry.size() > kKeptOdometry) odometry.pop_front();
  }

  void on_truth(const diagnostic_msgs::DiagnosticArrayConstPtr& message) {
    const std::optional<log::GroundTruth> truth =
        truth_from_message(*message, options.context_names);
    if (!truth) return;
    std::lock_guard<std::mutex> lock(mutex);
    truth_seen = true;
    truths[message->header.stamp.toNSec()] = *truth;
    while (truths.size() > kKeptTruths)
      truths.erase(truths.begin());
    arrived.notify_one();
  }
};

TopicInputs::TopicInputs(RosSession& session, TopicInputOptions options)
    : state_(std::make_unique<State>()) {
  State& s = *state_;
  s.options = std::move(options);
  ros::NodeHandle& node = *session.handles().node;
  const RosTopics& topics = s.options.topics;
  // Without TCP_NODELAY, Nagle's algorithm may hold a message's last segment back until the
  // previous one is acknowledged: latency for nothing, as each message is written whole. It
  // matters for the small messages too: the loop waits for a frame's ground truth.
  const ros::TransportHints no_delay = ros::TransportHints().tcpNoDelay();
  if (s.options.mode == InputMode::kCamera) {
    s.colour = std::make_unique<message_filters::Subscriber<sensor_msgs::Image>>(
        node, topics.colour, 2, no_delay);
    s.depth = std::make_unique<message_filters::Subscriber<sensor_msgs::Image>>(node, topics.depth,
                                                                                2, no_delay);
    s.info = std::make_unique<message_filters::Subscriber<sensor_msgs::CameraInfo>>(
        node, topics.camera_info, 2, no_delay);
    s.sync = std::make_unique<ImageSync>(*s.colour, *s.depth, *s.info, 10);
    s.sync->registerCallback(&State::on_images, &s);
  } else {
    s.subscribers.push_back(
        node.subscribe(topics.detections, 10, &State::on_detections, &s, no_delay));
    s.subscribers.push_back(node.subscribe<std_msgs::Float64>(
        topics.reward, 10,
        [&s](const std_msgs::Float64ConstPtr& message) {
          std::lock_guard<std::mutex> lock(s.mutex);
          s.reward = message->data;
        },
        ros::VoidConstPtr(), no_delay));
    s.subscribers.push_back(node.subscribe<std_msgs::Int8>(
        topics.treat_holder, 10,
        [&s](const std_msgs::Int8ConstPtr& message) {
          std::lock_guard<std::mutex> lock(s.mutex);
          s.holder = message->data;
        },
        ros::VoidConstPtr(), no_delay));
  }
  if (s.options.use_odom)
    s.subscribers.push_back(node.subscribe(topics.odom, 50, &State::on_odometry, &s, no_delay));
  s.subscribers.push_back(node.subscribe(topics.ground_truth, 10, &State::on_truth, &s, no_delay));
}

TopicInputs::~TopicInputs() {
  // Unsubscribe first, so that no callback runs into a half-destroyed state.
  state_->sync.reset();
  state_->colour.reset();
  state_->depth.reset();
  state_->info.reset();
  state_->subscribers.clear();
}

std::optional<ObservedInput> TopicInputs::next(std::chrono::milliseconds timeout) {
  State& s = *state_;
  std::unique_lock<std::mutex> lock(s.mutex);
  if (!s.arrived.wait_for(lock, timeout, [&] { return s.pending.has_value(); }))
    return std::nullopt;
  ObservedInput input = std::move(*s.pending);
  s.pending.reset();
  const std::uint64_t stamp = input.stamp_ns;
  if (s.truth_seen) s.arrived.wait_for(lock, kTruthWait, [&] { return s.truths.count(stamp) > 0; });
  const auto truth = s.truths.find(stamp);
  if (truth != s.truths.end()) input.truth = truth->second;
  return input;
}

std::string TopicInputs::describe() const {
  const RosTopics& topics = state_->options.topics;
  const ros::NodeHandle node;
  if (state_->options.mode == InputMode::kCamera)
    return "camera topics " + node.resolveName(topics.colour) + ", " +
           node.resolveName(topics.depth) + ", " + node.resolveName(topics.camera_info);
  return "detections " + node.resolveName(topics.detections) + " (reward " +
         node.resolveName(topics.reward) + ", holder " + node.resolveName(topics.treat_holder) +
         ")";
}

std::uint64_t TopicInputs::dropped() const {
  std::lock_guard<std::mutex> lock(state_->mutex);
  return state_->dropped;
}

std::uint64_t TopicInputs::refused() const {
  std::lock_guard<std::mutex> lock(state_->mutex);
  return state_->refused;
}

std::string TopicInputs::last_refusal() const {
  std::lock_guard<std::mutex> lock(state_->mutex);
  return state_->last_refusal;
}

}  // namespace oasis::hw::ros_node
