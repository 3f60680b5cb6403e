#include "camera/recorded_source.hpp"

#include <array>
#include <cstdint>
#include <fstream>
#include <optional>
#include <string>
#include <utility>
#include <variant>

#include <opencv2/imgcodecs.hpp>

#include "camera/camera_error.hpp"
#include "camera/recording_layout.hpp"
#include "camera/sequence_yaml.hpp"

namespace oasis::hw::camera {

namespace {

namespace fs = std::filesystem;

std::string pixel_type_name(int type) {
  switch (type) {
    case CV_8UC1:
      return "8-bit grey";
    case CV_8UC3:
      return "8-bit colour";
    case CV_8UC4:
      return "8-bit colour with alpha";
    case CV_16UC1:
      return "16-bit single-channel";
    case CV_16UC3:
      return "16-bit colour";
    default:
      return "OpenCV type " + std::to_string(type);
  }
}

std::string size_and_type(int width, int height, int type) {
  return std::to_string(width) + "x" + std::to_string(height) + " " + pixel_type_name(type);
}

void require_folder(const fs::path& folder) {
  std::error_code error;
  if (!fs::exists(folder, error))
    throw CameraError("recording folder " + folder.string() + " does not exist");
  if (!fs::is_directory(folder, error))
    throw CameraError("recording folder " + folder.string() + " is not a folder");
  if (!fs::exists(folder / kSequenceFileName, error))
    throw CameraError("recording folder " + folder.string() + " has no " +
                      std::string(kSequenceFileName) +
                      " (the writer adds it last: was the recording finished?)");
}

// Every frame file the description promises, so a truncated copy is refused before it plays.
void require_frame_files(const fs::path& folder, std::size_t frame_count) {
  std::error_code error;
  for (std::size_t i = 0; i < frame_count; ++i)
    for (const std::string& name : {colour_file_name(i), depth_file_name(i)})
      if (!fs::is_regular_file(folder / name, error))
        throw CameraError("recording " + folder.string() + " lacks frame file " + name + " (" +
                          std::string(kSequenceFileName) + " lists " + std::to_string(frame_count) +
                          " frames)");
}

// The width and height a PNG declares in its header (the IHDR chunk that must come first), or
// nullopt when the file does not start as a PNG. Read before decoding: a file of a few
// megabytes of compressed zeros can declare a frame of gigabytes, which cv::imread would
// allocate before any check of ours could refuse it.
std::optional<std::pair<std::uint32_t, std::uint32_t>> png_declared_size(const fs::path& file) {
  static constexpr std::array<unsigned char, 16> kStart = {
      0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n', 0, 0, 0, 13, 'I', 'H', 'D', 'R'};
  std::array<unsigned char, 24> header{};
  std::ifstream in(file, std::ios::binary);
  in.read(reinterpret_cast<char*>(header.data()), header.size());
  if (in.gcount() != static_cast<std::streamsize>(header.size())) return std::nullopt;
  for (std::size_t i = 0; i < kStart.size(); ++i)
    if (header[i] != kStart[i]) return std::nullopt;
  const auto big_endian = [&header](std::size_t at) {
    return (std::uint32_t{header[at]} << 24) | (std::uint32_t{header[at + 1]} << 16) |
           (std::uint32_t{header[at + 2]} << 8) | std::uint32_t{header[at + 3]};
  };
  return std::make_pair(big_endian(16), big_endian(20));
}

// The image, or why it is not the one sequence.yaml promises.
std::variant<cv::Mat, std::string> load_image(const fs::path& file, int type,
                                              const CameraIntrinsics& intrinsics) {
  std::error_code ignored;
  if (!fs::is_regular_file(file, ignored))
    return file.string() + " is missing (deleted during playback?)";
  const auto declared = png_declared_size(file);
  if (!declared) return file.string() + " is not a PNG image";
  if (declared->first != static_cast<std::uint32_t>(intrinsics.width) ||
      declared->second != static_cast<std::uint32_t>(intrinsics.height))
    return file.string() + " declares " + std::to_string(declared->first) + "x" +
           std::to_string(declared->second) + " pixels, but sequence.yaml promises " +
           std::to_string(intrinsics.width) + "x" + std::to_string(intrinsics.height) +
           " (not decoded)";
  cv::Mat image;
  try {
    image = cv::imread(file.string(), cv::IMREAD_UNCHANGED);  // no conversion: check the type
  } catch (const cv::Exception& error) {
    return "cannot decode " + file.string() + ": " + error.what();
  }
  if (image.empty()) return "cannot read " + file.string() + " as an image";
  if (image.type() != type || image.cols != intrinsics.width || image.rows != intrinsics.height)
    return file.string() + " is " + size_and_type(image.cols, image.rows, image.type()) +
           ", but sequence.yaml promises " +
           size_and_type(intrinsics.width, intrinsics.height, type);
  return image;
}

}  // namespace

RecordedSource::RecordedSource(std::filesystem::path folder) : folder_(std::move(folder)) {
  require_folder(folder_);
  description_ = read_sequence_yaml(folder_ / kSequenceFileName);
  require_frame_files(folder_, description_.frame_count());
}

NextFrame RecordedSource::next() {
  truth_of_last_frame_.reset();
  if (next_index_ >= description_.frame_count()) return SourceStop{SourceStop::Kind::kEnd, {}};
  const CameraIntrinsics& intrinsics = description_.intrinsics;
  auto colour = load_image(folder_ / colour_file_name(next_index_), CV_8UC3, intrinsics);
  if (auto* reason = std::get_if<std::string>(&colour))
    return SourceStop{SourceStop::Kind::kFailure, *reason};
  auto depth = load_image(folder_ / depth_file_name(next_index_), CV_16UC1, intrinsics);
  if (auto* reason = std::get_if<std::string>(&depth))
    return SourceStop{SourceStop::Kind::kFailure, *reason};

  Frame frame;
  frame.colour = std::get<cv::Mat>(std::move(colour));
  frame.depth = std::get<cv::Mat>(std::move(depth));
  frame.depth_scale_m_per_unit = description_.depth_scale_m_per_unit;
  frame.intrinsics = intrinsics;
  frame.timestamp_s = description_.timestamps_s[next_index_];
  if (description_.has_truth()) truth_of_last_frame_ = description_.truth[next_index_];
  ++next_index_;
  return frame;
}

}  // namespace oasis::hw::camera
