#include "loop/robot_link.hpp"

namespace oasis::hw::loop {

void DryRunLink::command(const go1::VelocityCommand& velocity, double time_s) {
  if (time_s > current_since_s_) pose_ = go1::advanced(pose_, current_, time_s - current_since_s_);
  current_ = velocity;
  current_since_s_ = time_s;
}

}  // namespace oasis::hw::loop
