#pragma once
// What the loop asks of a controller each step: perception's result in, the step's record (the
// belief, the chosen abstraction, the action and its velocity) out. The attention filter is the
// controller of oasis-go1 (attention_controller.hpp); the simulator also runs baselines through
// the same loop, such as the oracle that is told the true context (oracle_controller.hpp).
#include "go1/planar_pose.hpp"
#include "log/step_record.hpp"
#include "perception/perception_result.hpp"

namespace oasis::hw::loop {

class LoopController {
 public:
  virtual ~LoopController() = default;
  // `robot` is the robot's odometry pose when the frame was taken.
  virtual log::StepRecord decide(const PerceptionResult& seen, double time_s,
                                 const go1::Pose& robot) = 0;
};

}  // namespace oasis::hw::loop
