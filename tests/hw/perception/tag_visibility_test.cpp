// Whether a carried treat tag can be in the image, and so whether "no tag seen" means reward 0.
#include "perception/tag_visibility.hpp"

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

TEST(TagVisibility, TheRewardIsUnknownOnlyWhenSomeoneInReachCouldHideTheirTag) {
  const CameraIntrinsics intrinsics;
  const CameraMount mount;
  const CarriedTag tag;
  const ReachRegion reach;  // 0.3 to 0.8 m ahead, 0.25 m to either side
  const HumanEstimate far = seen_at(3.0, 1.0);
  EXPECT_FALSE(reward_is_known({seen_at(0.35, 0.0), far}, TreatHolder::kNone, reach, intrinsics,
                               mount, tag));
  EXPECT_TRUE(
      reward_is_known({seen_at(0.7, 0.0), far}, TreatHolder::kNone, reach, intrinsics, mount, tag));
  // A holder found decides; someone unseen, or too near but outside the reach region, does not
  // make it unknown.
  EXPECT_TRUE(reward_is_known({seen_at(0.35, 0.0), far}, TreatHolder::kHuman2, reach, intrinsics,
                              mount, tag));
  HumanEstimate unseen = seen_at(0.35, 0.0);
  unseen.seen = false;
  EXPECT_TRUE(reward_is_known({unseen, far}, TreatHolder::kNone, reach, intrinsics, mount, tag));
  EXPECT_TRUE(
      reward_is_known({seen_at(0.2, 0.0), far}, TreatHolder::kNone, reach, intrinsics, mount, tag));
}

}  // namespace
}  // namespace oasis::hw
