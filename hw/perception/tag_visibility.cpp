#include "perception/tag_visibility.hpp"

#include <cmath>

namespace oasis::hw {

bool tag_fits_in_image(const CameraIntrinsics& intrinsics, const CameraMount& mount,
                       const CarriedTag& tag, double x_m, double y_m) {
  const double half = tag.black_edge_m / 2.0;
  for (const double side : {-half, half})
    for (const double up : {-half, half})
      if (!projects_inside_image(intrinsics, mount, {x_m, y_m + side, tag.centre_height_m + up},
                                 tag.edge_margin_px))
        return false;
  return true;
}

bool tag_would_show(const CameraIntrinsics& intrinsics, const CameraMount& mount,
                    const CarriedTag& tag, double x_m, double y_m) {
  return std::hypot(x_m, y_m) <= tag.max_range_m &&
         tag_fits_in_image(intrinsics, mount, tag, x_m, y_m);
}

void mark_tag_visibility(std::array<HumanEstimate, 2>& humans, const CameraIntrinsics& intrinsics,
                         const CameraMount& mount, const CarriedTag& tag) {
  for (HumanEstimate& human : humans)
    human.tag_would_show =
        human.seen && tag_would_show(intrinsics, mount, tag, human.x_m, human.y_m);
}

bool reward_is_known(const std::array<HumanEstimate, 2>& humans, TreatHolder holder,
                     const ReachRegion& reach) {
  if (holder != TreatHolder::kNone) return true;
  for (const HumanEstimate& human : humans)
    if (human.seen && reach.contains(human.x_m, human.y_m) && !human.tag_would_show) return false;
  return true;
}

}  // namespace oasis::hw
