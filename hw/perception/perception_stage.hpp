// What the loop asks of perception: a frame in, the two people, the treat holder and the
// reward out. Perception (perception.hpp) is the real one; a simulator may answer from its own
// ground truth instead (hw/sim's fast path), without pixels.
#pragma once

#include "perception/frame.hpp"
#include "perception/perception_result.hpp"

namespace oasis::hw {

class PerceptionStage {
 public:
  virtual ~PerceptionStage() = default;
  virtual PerceptionResult step(const Frame& frame) = 0;
};

}  // namespace oasis::hw
