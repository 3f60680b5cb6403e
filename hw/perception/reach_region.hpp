// The reward region of specs/go1_treat.oasis, "within reach in front of the robot":
// 0.3 <= x <= 0.8 and -0.25 <= y <= 0.25 (metres, robot frame), bounds inclusive.
#pragma once

namespace oasis::hw {

struct ReachRegion {
  double x_min_m = 0.3;
  double x_max_m = 0.8;
  double y_min_m = -0.25;
  double y_max_m = 0.25;

  bool contains(double x_m, double y_m) const {
    return x_m >= x_min_m && x_m <= x_max_m && y_m >= y_min_m && y_m <= y_max_m;
  }
};

}  // namespace oasis::hw
