#include "ros/bag_feed.hpp"

#include <cerrno>
#include <deque>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>

#include <diagnostic_msgs/DiagnosticArray.h>
#include <geometry_msgs/PoseArray.h>
#include <nav_msgs/Odometry.h>
#include <ros/time.h>
#include <rosbag/bag.h>
#include <rosbag/exceptions.h>
#include <rosbag/view.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <std_msgs/Float64.h>
#include <std_msgs/Int8.h>
#include <sys/stat.h>

#include "files/input_file.hpp"
#include "ros/message_conversion.hpp"
#include "text/printable_text.hpp"

namespace oasis::hw::ros_node {
namespace {

// Bags name topics as they were published; the settings name them relative to the node.
std::string relative(const std::string& topic) {
  return topic.empty() || topic.front() != '/' ? topic : topic.substr(1);
}

struct CameraParts {
  sensor_msgs::ImageConstPtr colour;
  sensor_msgs::ImageConstPtr depth;
  sensor_msgs::CameraInfoConstPtr info;
  bool complete() const { return colour && depth && info; }
};

// Why `path` cannot be a bag, or "". The rule of every program's inputs
// (common/files/input_file.hpp: a directory, a device or a socket is refused with what it is),
// and a FIFO too: rosbag reads a bag by seeking in it (the index is at the end), and a FIFO
// nobody writes to blocked its open() forever.
std::string bag_file_problem(const std::string& path) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) return files::reason_of_errno(errno);
  if (const std::optional<std::string> refused = files::refused_kind(info)) return *refused;
  if (S_ISFIFO(info.st_mode))
    return "is a pipe; a rosbag is read by seeking in it, so it must be a regular file";
  return "";
}

}  // namespace

struct BagFeed::State {
  std::string path;
  TopicInputOptions options;
  bool camera = true;
  rosbag::Bag bag;
  std::unique_ptr<rosbag::View> view;
  rosbag::View::iterator at;
  std::set<std::string> held;  // every topic in the bag, for the error message

  std::map<std::uint64_t, CameraParts> camera_parts;         // by stamp, until complete
  std::map<std::uint64_t, log::GroundTruth> truths;          // by stamp
  std::deque<std::pair<std::uint64_t, go1::Pose>> odometry;  // in bag order, the latest few
  std::optional<double> reward;
  std::optional<int> holder;
  std::uint64_t refused = 0;
  std::string last_refusal;
  std::uint64_t given = 0;
  bool done = false;

  bool is(const std::string& topic, const std::string& setting) const {
    return topic == relative(setting);
  }

  void finish(ObservedInput& input) const {
    // The pose at the stamp: that stamp's odometry, or the latest before it, as live.
    for (auto it = odometry.rbegin(); it != odometry.rend(); ++it)
      if (it->first <= input.stamp_ns) {
        input.odometry = it->second;
        break;
      }
    const auto truth = truths.find(input.stamp_ns);
    if (truth != truths.end()) input.truth = truth->second;
  }

  // Reads one message; an observation when it completes one.
  std::optional<ObservedInput> read(const rosbag::MessageInstance& message) {
    const RosTopics& t = options.topics;
    const std::string topic = relative(message.getTopic());
    if (is(topic, t.odom) && options.use_odom) {
      if (auto odom = message.instantiate<nav_msgs::Odometry>()) {
        odometry.emplace_back(odom->header.stamp.toNSec(), pose_from_odometry(*odom));
        if (odometry.size() > 200) odometry.pop_front();
      }
    } else if (is(topic, t.ground_truth)) {
      if (auto truth = message.instantiate<diagnostic_msgs::DiagnosticArray>())
        if (auto read = truth_from_message(*truth, options.context_names)) {
          truths[truth->header.stamp.toNSec()] = *read;
          while (truths.size() > 50)
            truths.erase(truths.begin());
        }
    } else if (camera && (is(topic, t.colour) || is(topic, t.depth))) {
      if (auto image = message.instantiate<sensor_msgs::Image>()) {
        CameraParts& parts = camera_parts[image->header.stamp.toNSec()];
        (is(topic, t.colour) ? parts.colour : parts.depth) = image;
        return completed(image->header.stamp.toNSec());
      }
    } else if (camera && is(topic, t.camera_info)) {
      if (auto info = message.instantiate<sensor_msgs::CameraInfo>()) {
        camera_parts[info->header.stamp.toNSec()].info = info;
        return completed(info->header.stamp.toNSec());
      }
    } else if (!camera && is(topic, t.reward)) {
      if (auto value = message.instantiate<std_msgs::Float64>()) reward = value->data;
    } else if (!camera && is(topic, t.treat_holder)) {
      if (auto value = message.instantiate<std_msgs::Int8>()) holder = value->data;
    } else if (!camera && is(topic, t.detections)) {
      if (auto positions = message.instantiate<geometry_msgs::PoseArray>()) {
        ObservedInput input;
        input.detections = perception_from_detections({*positions, reward, holder});
        input.stamp_ns = positions->header.stamp.toNSec();
        input.stamp_s = positions->header.stamp.toSec();
        return input;
      }
    }
    return std::nullopt;
  }

  // The camera observation of `stamp` once its three messages are in, as the synchroniser
  // makes one live. Older incomplete stamps are dropped, as the synchroniser drops them.
  std::optional<ObservedInput> completed(std::uint64_t stamp) {
    const auto parts = camera_parts.find(stamp);
    if (parts == camera_parts.end() || !parts->second.complete()) return std::nullopt;
    ObservedInput input;
    input.stamp_ns = stamp;
    input.stamp_s = parts->second.colour->header.stamp.toSec();
    const CameraParts complete = parts->second;
    camera_parts.erase(camera_parts.begin(), std::next(parts));
    input.frame = frame_from_messages(*complete.colour, *complete.depth, *complete.info);
    return input;
  }
};

BagFeed::BagFeed(const std::string& path, TopicInputOptions options)
    : state_(std::make_unique<State>()) {
  State& s = *state_;
  s.path = path;
  s.options = std::move(options);
  s.camera = s.options.mode == InputMode::kCamera;
  if (!ros::Time::isValid()) ros::Time::init();
  if (const std::string problem = bag_file_problem(path); !problem.empty())
    throw RosError("--bag " + text::printable_excerpt(path, 1000) + ": " + problem);
  try {
    s.bag.open(path, rosbag::bagmode::Read);
  } catch (const rosbag::BagException& e) {
    throw RosError("--bag " + path + ": " + e.what());
  }
  s.view = std::make_unique<rosbag::View>(s.bag);
  const RosTopics& t = s.options.topics;
  bool has_input = false;
  for (const rosbag::ConnectionInfo* connection : s.view->getConnections()) {
    const std::string topic = relative(connection->topic);
    s.held.insert(topic);
    has_input = has_input || (s.camera ? s.is(topic, t.colour) : s.is(topic, t.detections));
  }
  if (!has_input) {
    std::string topics;
    for (const std::string& topic : s.held)
      topics += (topics.empty() ? "" : ", ") + topic;
    throw RosError("--bag " + path + ": no messages on " +
                   relative(s.camera ? t.colour : t.detections) + " (ros.mode " +
                   (s.camera ? "camera" : "detections") +
                   "); the bag holds: " + (topics.empty() ? "nothing" : topics));
  }
  s.at = s.view->begin();
}

BagFeed::~BagFeed() = default;

std::optional<ObservedInput> BagFeed::next(std::chrono::milliseconds) {
  State& s = *state_;
  while (s.at != s.view->end()) {
    const rosbag::MessageInstance& message = *s.at;
    std::optional<ObservedInput> input;
    try {
      input = s.read(message);
    } catch (const std::invalid_argument& e) {
      ++s.refused;  // a malformed message: the replay goes on without it, as the node does
      s.last_refusal = e.what();
    }
    ++s.at;
    if (!input) continue;
    s.finish(*input);
    ++s.given;
    return input;
  }
  s.done = true;
  return std::nullopt;
}

bool BagFeed::ended() const {
  return state_->done;
}

std::string BagFeed::describe() const {
  return "bag " + state_->path + " (" + std::to_string(state_->view->size()) + " messages)";
}

std::uint64_t BagFeed::refused() const {
  return state_->refused;
}

std::string BagFeed::last_refusal() const {
  return state_->last_refusal;
}

}  // namespace oasis::hw::ros_node
