// What perception reports about one person.
#pragma once

#include <opencv2/core/types.hpp>

namespace oasis::hw {

struct HumanEstimate {
  bool seen = false;  // false: no plausible shirt of this colour; the rest is meaningless
  double x_m = 0.0;   // robot frame, centre of the shirt's front surface
  double y_m = 0.0;
  double confidence = 0.0;  // 0..1; below 1 when the shirt is cut off or depth is sparse
  double depth_m = 0.0;     // median optical z-depth of the shirt
  cv::Rect pixel_box;       // the shirt blob's bounding box in the image
  // Were this person carrying the treat tag (tag_visibility.hpp), would it be decoded: near
  // enough, its whole black square in the image? Set by perception for everyone seen.
  bool tag_would_show = false;
};

}  // namespace oasis::hw
