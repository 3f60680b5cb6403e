// Whether a carried treat tag can be in the image, and so whether "no tag seen" means reward 0.
#include "perception/tag_visibility.hpp"

#include <array>

#include <gtest/gtest.h>

namespace oasis::hw {
namespace {

HumanEstimate seen_at(double x_m, double y_m) {
  HumanEstimate human;
  human.seen = true;
  human.x_m = x_m;
  human.y_m = y_m;
  return human;
}

TEST(TagVisibility, NearTheRobotTheTagLeavesTheTopOfTheImage) {
  const CameraIntrinsics intrinsics;
  const CameraMount mount;
  const CarriedTag tag;
  EXPECT_FALSE(tag_fits_in_image(intrinsics, mount, tag, 0.35, 0.0));
  EXPECT_TRUE(tag_fits_in_image(intrinsics, mount, tag, 0.7, 0.0));
  EXPECT_TRUE(tag_fits_in_image(intrinsics, mount, tag, 3.0, 0.0));
  EXPECT_FALSE(tag_fits_in_image(intrinsics, mount, tag, 1.0, 1.5));   // beside the view
  EXPECT_FALSE(tag_fits_in_image(intrinsics, mount, tag, -1.0, 0.0));  // behind the camera
  // Carried lower, it stays in the image nearer the robot.
  CarriedTag low = tag;
  low.centre_height_m = 0.6;
  EXPECT_TRUE(tag_fits_in_image(intrinsics, mount, low, 0.35, 0.0));
}

TEST(TagVisibility, BeyondItsRangeATagDoesNotShow) {
  const CameraIntrinsics intrinsics;
  const CameraMount mount;
  const CarriedTag tag;  // 4 m
  EXPECT_TRUE(tag_would_show(intrinsics, mount, tag, 3.9, 0.0));
  EXPECT_FALSE(tag_would_show(intrinsics, mount, tag, 4.1, 0.0));
  EXPECT_FALSE(tag_would_show(intrinsics, mount, tag, 0.35, 0.0));  // out of the image
}

// Human 1 at `x1` straight ahead, human 2 far to the side, both seen, marked as perception does.
std::array<HumanEstimate, 2> marked(double x1) {
  std::array<HumanEstimate, 2> humans{seen_at(x1, 0.0), seen_at(3.0, 1.0)};
  mark_tag_visibility(humans, CameraIntrinsics{}, CameraMount{}, CarriedTag{});
  return humans;
}

TEST(TagVisibility, MarksWhoseTagWouldShow) {
  EXPECT_FALSE(marked(0.35)[0].tag_would_show);
  EXPECT_TRUE(marked(0.7)[0].tag_would_show);
  EXPECT_TRUE(marked(0.7)[1].tag_would_show);
  std::array<HumanEstimate, 2> humans = marked(0.7);
  humans[0].seen = false;
  mark_tag_visibility(humans, CameraIntrinsics{}, CameraMount{}, CarriedTag{});
  EXPECT_FALSE(humans[0].tag_would_show);  // nobody seen, nothing to say
}

TEST(TagVisibility, TheRewardIsUnknownOnlyWhenSomeoneInReachCouldHideTheirTag) {
  const ReachRegion reach;  // 0.3 to 0.8 m ahead, 0.25 m to either side
  EXPECT_FALSE(reward_is_known(marked(0.35), TreatHolder::kNone, reach));
  EXPECT_TRUE(reward_is_known(marked(0.7), TreatHolder::kNone, reach));
  // A holder found decides; someone unseen, or too near but outside the reach region, does not
  // make it unknown.
  EXPECT_TRUE(reward_is_known(marked(0.35), TreatHolder::kHuman2, reach));
  std::array<HumanEstimate, 2> unseen = marked(0.35);
  unseen[0].seen = false;
  EXPECT_TRUE(reward_is_known(unseen, TreatHolder::kNone, reach));
  EXPECT_TRUE(reward_is_known(marked(0.2), TreatHolder::kNone, reach));
}

}  // namespace
}  // namespace oasis::hw
