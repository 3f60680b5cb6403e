#pragma once
// What oasis-ros tells the rest of the robot about its attention, each step:
//   ~belief   std_msgs/Float64MultiArray: one probability per catalog context, in catalog
//             order; layout.dim[0] has label "contexts" and size N, and the context names, in
//             the same order, are dim[1..N]'s labels (size 1 each), so a subscriber needs
//             nothing else to name the numbers
//   ~context  std_msgs/String: the name of the abstraction attended this step
//   ~markers  visualization_msgs/MarkerArray in the base frame: the attended abstraction's
//             cells around the robot (the current one highlighted), the people as the filter
//             saw them, and the reward region
//
// The markers (REP-103: x forward, y left, metres; flat ones just above z = 0). Every step sends
// the same slots, in the same order, each either drawn (ADD) or removed (DELETE), so that rviz
// replaces them and never keeps a stale one; lifetime 0, frame_locked false.
//   reach 0         the reward region, a green translucent flat CUBE
//   cells k         the slice of the attended abstraction's partition through the current state
//                   in which person k+1's (x, y) vary and every other variable keeps its value:
//                   for a gridded abstraction the exact boundaries between blocks (LINE_LIST,
//                   each grid line's runs merged, the slice's outline included), in the person's
//                   colour; for a BSP (or a grid too fine to draw in 1500 points) the slice
//                   sampled every 0.1 m or coarser, at most 1200 flat cubes (CUBE_LIST), each
//                   coloured by its block. Removed when the abstraction does not attend to
//                   person k+1 (its partition does not change along that slice)
//   current_cell k  the part of slice k in the current state's block, filled in cyan
//                   (TRIANGLE_LIST of rectangles; CUBE_LIST of samples when sampled); removed
//                   when the state is outside the abstraction's domain
//   people k        person k+1: a SPHERE, red (human 1) or yellow (human 2) where perception
//                   saw them; when not seen, grey where the filter holds them (the state), or
//                   removed if the record has no state
//   people k+2      the label "human 1" / "human 2" (" (not seen)") over the sphere
// Cells are drawn only for a continuous catalog over at least (x1, y1, x2, y2), a state with all
// its variables and an attended abstraction whose partition is well formed; otherwise only the
// people and the reach region, never an exception.
#include <string>
#include <vector>

#include <ros/node_handle.h>
#include <ros/publisher.h>
#include <std_msgs/Float64MultiArray.h>
#include <visualization_msgs/MarkerArray.h>

#include "log/step_record.hpp"
#include "oasis/rt/catalog_view.hpp"
#include "perception/reach_region.hpp"

namespace oasis::hw::ros_node {

// The context names of a catalog, in its order.
std::vector<std::string> context_names(const rt::CatalogView& catalog);

// record.belief with the layout above; a number beyond the names is labelled by its index.
std_msgs::Float64MultiArray belief_message(const log::StepRecord& record,
                                           const std::vector<std::string>& names);

// The ~markers of one step (the slots above).
visualization_msgs::MarkerArray attention_markers(const rt::CatalogView& catalog,
                                                  const log::StepRecord& record,
                                                  const ReachRegion& reach,
                                                  const std::string& base_frame,
                                                  const ros::Time& stamp);

class AttentionTopics {
 public:
  // Advertises ~belief, ~context and ~markers on `private_node`.
  AttentionTopics(ros::NodeHandle& private_node, const rt::CatalogView& catalog, ReachRegion reach,
                  std::string base_frame);

  // Publishes one step: the belief, the context and, when someone subscribes, the markers.
  void publish(const log::StepRecord& record, const ros::Time& stamp);

 private:
  const rt::CatalogView& catalog_;
  std::vector<std::string> names_;
  ReachRegion reach_;
  std::string base_frame_;
  ros::Publisher belief_;
  ros::Publisher context_;
  ros::Publisher markers_;
};

}  // namespace oasis::hw::ros_node
