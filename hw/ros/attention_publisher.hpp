#pragma once
// The ROS-free face of attention_topics.hpp, for the C++20 node: publishes each step's belief,
// attended context and markers (the topics and their layout: attention_topics.hpp).
#include <memory>
#include <string>

#include "log/step_record.hpp"
#include "oasis/rt/catalog_view.hpp"
#include "perception/reach_region.hpp"
#include "ros/ros_session.hpp"

namespace oasis::hw::ros_node {

class AttentionTopics;

class AttentionPublisher {
 public:
  AttentionPublisher(RosSession& session, const rt::CatalogView& catalog, ReachRegion reach,
                     std::string base_frame);
  ~AttentionPublisher();
  AttentionPublisher(const AttentionPublisher&) = delete;
  AttentionPublisher& operator=(const AttentionPublisher&) = delete;

  // `stamp_s`: the stamp of the observation the step decided on.
  void publish(const log::StepRecord& record, double stamp_s);

 private:
  std::unique_ptr<AttentionTopics> topics_;
};

}  // namespace oasis::hw::ros_node
