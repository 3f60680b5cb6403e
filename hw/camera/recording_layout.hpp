#pragma once
// The names of the files inside a recording folder, shared by the writer and the reader:
// sequence.yaml, then colour_000000.png and depth_000000.png for frame 0, and so on.

#include <cstddef>
#include <string>
#include <string_view>

namespace oasis::hw::camera {

inline constexpr std::string_view kSequenceFileName = "sequence.yaml";

std::string colour_file_name(std::size_t frame_index);  // "colour_000042.png"
std::string depth_file_name(std::size_t frame_index);   // "depth_000042.png"

// True for the names above (any index): the files a writer may replace.
bool is_recording_file_name(std::string_view name);

}  // namespace oasis::hw::camera
