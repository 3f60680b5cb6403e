// Could the camera see the treat tag on a person, if that person held it? The tag is carried
// upright facing the robot at a known height; it can be decoded only when its whole black
// square is in the image. Near the robot it leaves the top of the image before the shirt does
// (nearer than about 0.45 m with the default mount), so perception cannot tell a holder standing
// that close from someone without the treat: the reward it would report there is unknown.
#pragma once

#include <array>

#include "perception/camera_mount.hpp"
#include "perception/frame.hpp"
#include "perception/human_estimate.hpp"
#include "perception/reach_region.hpp"
#include "perception/treat_holder.hpp"

namespace oasis::hw {

struct CarriedTag {
  double black_edge_m = 0.20;    // the printed tag's black square
  double centre_height_m = 1.1;  // where the holder carries it, above the floor
  double edge_margin_px = 8.0;   // nearer the image border than this it may not be decoded
  double max_range_m = 4.0;      // farther, too few pixels to decode reliably (19 px at 4 m)
};

// Is the whole black square of a tag carried by someone standing at (x_m, y_m) (robot frame)
// inside the image?
bool tag_fits_in_image(const CameraIntrinsics& intrinsics, const CameraMount& mount,
                       const CarriedTag& tag, double x_m, double y_m);

// Would such a tag be decoded: within max_range_m and wholly in the image?
bool tag_would_show(const CameraIntrinsics& intrinsics, const CameraMount& mount,
                    const CarriedTag& tag, double x_m, double y_m);

// Sets HumanEstimate::tag_would_show for each person seen (false for the others).
void mark_tag_visibility(std::array<HumanEstimate, 2>& humans, const CameraIntrinsics& intrinsics,
                         const CameraMount& mount, const CarriedTag& tag);

// Whether the reward perception reports is known: always when a holder was found; with no tag
// seen, not when someone seen stands in the reach region without tag_would_show (their tag,
// were they holding it, out of the image). Needs mark_tag_visibility() first.
bool reward_is_known(const std::array<HumanEstimate, 2>& humans, TreatHolder holder,
                     const ReachRegion& reach);

}  // namespace oasis::hw
