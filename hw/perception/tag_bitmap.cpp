#include "perception/tag_bitmap.hpp"

#include <memory>
#include <stdexcept>
#include <string>

#include <apriltag/apriltag.h>
#include <apriltag/common/image_u8.h>
#include <apriltag/tag36h11.h>

namespace oasis::hw {

cv::Mat tag36h11_bitmap(int id) {
  const std::unique_ptr<apriltag_family_t, void (*)(apriltag_family_t*)> family(tag36h11_create(),
                                                                                tag36h11_destroy);
  if (id < 0 || static_cast<std::uint32_t>(id) >= family->ncodes)
    throw std::out_of_range("tag36h11 has no id " + std::to_string(id));
  const std::unique_ptr<image_u8_t, void (*)(image_u8_t*)> image(
      apriltag_to_image(family.get(), id), image_u8_destroy);
  const cv::Mat view(image->height, image->width, CV_8UC1, image->buf,
                     static_cast<std::size_t>(image->stride));
  return view.clone();
}

}  // namespace oasis::hw
