#pragma once
// Observations from a rosbag, for replaying a run offline (oasis-ros --bag): the same topics
// the node would subscribe to, matched the same way (camera images by stamp; detections with
// the latest reward and holder before them), each with the odometry and ground truth of its
// stamp. No master is needed. ROS-free header.
#include <cstdint>
#include <memory>
#include <string>

#include "ros/topic_inputs.hpp"

namespace oasis::hw::ros_node {

class BagFeed final : public InputFeed {
 public:
  // Reads the whole bag's index and the messages of the topics it needs. Throws RosError when
  // the bag cannot be read or holds none of the input topics (naming those it does hold).
  BagFeed(const std::string& path, TopicInputOptions options);
  ~BagFeed() override;

  std::optional<ObservedInput> next(std::chrono::milliseconds timeout) override;
  bool ended() const override;
  std::string describe() const override;

  std::uint64_t refused() const;     // messages that could not be read
  std::string last_refusal() const;  // why the last of them could not

  struct State;  // bag_feed.cpp

 private:
  std::unique_ptr<State> state_;
};

}  // namespace oasis::hw::ros_node
