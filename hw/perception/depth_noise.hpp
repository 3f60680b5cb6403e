// Depth noise of a stereo camera: its standard deviation grows with distance (the stereo
// error grows as z squared; the constant and linear terms cover matching and calibration).
#pragma once

namespace oasis::hw {

struct DepthNoise {
  double constant_m = 0.0;  // a
  double linear = 0.0;      // b, metres per metre
  double quadratic = 0.0;   // c, metres per square metre

  // sigma(d) = a + b d + c d^2
  double sigma_at(double depth_m) const {
    return constant_m + linear * depth_m + quadratic * depth_m * depth_m;
  }

  // Roughly a D435 at 640x480: 2 mm + 0.2% of d + 0.5% of d^2, i.e. 3 cm at 2 m, 9 cm at 4 m.
  static DepthNoise realsense_like() { return {0.002, 0.002, 0.005}; }
};

}  // namespace oasis::hw
