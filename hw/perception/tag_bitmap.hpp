// The tag36h11 bitmap of one id, taken from libapriltag itself so the synthetic tag is exactly
// what the detector looks for.
#pragma once

#include <opencv2/core/mat.hpp>

namespace oasis::hw {

// A 10x10 CV_8UC1 image: a one-cell white ring, the black border, the 6x6 data bits
// (white = 255). Throws std::out_of_range for an id outside the family.
cv::Mat tag36h11_bitmap(int id);

}  // namespace oasis::hw
