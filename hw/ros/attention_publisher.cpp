#include "ros/attention_publisher.hpp"

#include "ros/attention_topics.hpp"
#include "ros/ros_session_handles.hpp"

namespace oasis::hw::ros_node {

AttentionPublisher::AttentionPublisher(RosSession& session, const rt::CatalogView& catalog,
                                       ReachRegion reach, std::string base_frame)
    : topics_(std::make_unique<AttentionTopics>(*session.handles().private_node, catalog, reach,
                                                std::move(base_frame))) {}

AttentionPublisher::~AttentionPublisher() = default;

void AttentionPublisher::publish(const log::StepRecord& record, double stamp_s) {
  topics_->publish(record, ros::Time(stamp_s));
}

}  // namespace oasis::hw::ros_node
