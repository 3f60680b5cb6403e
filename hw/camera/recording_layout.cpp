#include "camera/recording_layout.hpp"

#include <algorithm>
#include <cstdio>

namespace oasis::hw::camera {

namespace {

std::string numbered(std::string_view prefix, std::size_t frame_index) {
  char digits[32];
  std::snprintf(digits, sizeof digits, "%06zu", frame_index);
  return std::string(prefix) + digits + ".png";
}

bool is_numbered(std::string_view name, std::string_view prefix) {
  constexpr std::string_view kSuffix = ".png";
  if (!name.starts_with(prefix) || !name.ends_with(kSuffix)) return false;
  const std::string_view digits =
      name.substr(prefix.size(), name.size() - prefix.size() - kSuffix.size());
  return digits.size() >= 6 &&
         std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; });
}

}  // namespace

std::string colour_file_name(std::size_t frame_index) {
  return numbered("colour_", frame_index);
}

std::string depth_file_name(std::size_t frame_index) {
  return numbered("depth_", frame_index);
}

bool is_recording_file_name(std::string_view name) {
  return name == kSequenceFileName || is_numbered(name, "colour_") || is_numbered(name, "depth_");
}

}  // namespace oasis::hw::camera
