#pragma once
// The one exception type of the camera layer: a recording folder that is not a valid recording,
// a device that cannot be opened or streamed. Its message names the file or device, and for
// sequence.yaml the line and column, so the user knows what to fix.

#include <stdexcept>

namespace oasis::hw::camera {

class CameraError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace oasis::hw::camera
