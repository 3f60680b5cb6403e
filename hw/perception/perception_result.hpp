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
  // False when no tag was seen but someone seen stands in the reach region with their tag, were
  // they holding it, out of the image (tag_visibility.hpp): the 0 above then says nothing.
  bool reward_known = true;
};

}  // namespace oasis::hw
