// What one perception step reports: the two people, who holds the treat, and the reward.
#pragma once

#include <array>
#include <optional>

#include "perception/human_estimate.hpp"
#include "perception/tag_detector.hpp"
#include "perception/treat_holder.hpp"

namespace oasis::hw {

struct PerceptionResult {
  std::array<HumanEstimate, 2> humans;  // [0] human 1 (red shirt), [1] human 2 (yellow shirt)
  TreatHolder holder = TreatHolder::kNone;
  std::optional<TagDetection> treat_tag;  // the tag that decided the holder
  double reward = 0.0;                    // 1 when the holder stands within the reach region
};

}  // namespace oasis::hw
