// The reader on folders that are not whole recordings: each problem is refused at construction
// (folder, sequence.yaml, missing frame files) or, for pixels, reported as a failure naming the
// file when that frame is reached.
#include <string>
#include <variant>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "camera/camera_error.hpp"
#include "camera/recorded_source.hpp"
#include "temporary_folder.hpp"

namespace oasis::hw::camera {
namespace {

namespace fs = std::filesystem;
using testing::TemporaryFolder;
using testing::write_text;

const std::string kTwoFrames =
    "intrinsics: {fx: 100, fy: 100, cx: 15.5, cy: 11.5, width: 32, height: 24}\n"
    "depth_scale_m_per_unit: 0.001\n"
    "frame_count: 2\n"
    "frame_period_s: 0.1\n"
    "start_time_s: 5\n";

// Two 32x24 frames as sequence.yaml promises, written directly with OpenCV.
void write_two_frames(const TemporaryFolder& folder) {
  write_text(folder / "sequence.yaml", kTwoFrames);
  for (const char* index : {"000000", "000001"}) {
    cv::imwrite((folder / (std::string("colour_") + index + ".png")).string(),
                cv::Mat(24, 32, CV_8UC3, cv::Scalar(10, 20, 30)));
    cv::imwrite((folder / (std::string("depth_") + index + ".png")).string(),
                cv::Mat(24, 32, CV_16UC1, cv::Scalar(1234)));
  }
}

std::string construction_error(const fs::path& folder) {
  try {
    RecordedSource source(folder);
  } catch (const CameraError& error) {
    return error.what();
  }
  return "";
}

// The reason of the failure `next()` gives at the first frame, checked to be a failure.
std::string first_frame_failure(const fs::path& folder) {
  RecordedSource source(folder);
  const NextFrame next = source.next();
  if (!std::holds_alternative<SourceStop>(next)) return "a frame";
  const SourceStop& stop = std::get<SourceStop>(next);
  EXPECT_EQ(stop.kind, SourceStop::Kind::kFailure);
  const NextFrame again = source.next();  // a broken frame is not skipped
  EXPECT_TRUE(std::holds_alternative<SourceStop>(again));
  return stop.reason;
}

TEST(RecordedSource, PlaysHandWrittenRecordingWithPeriod) {
  const TemporaryFolder folder;
  write_two_frames(folder);
  RecordedSource source(folder.path());
  const NextFrame first = source.next();
  ASSERT_TRUE(std::holds_alternative<Frame>(first));
  EXPECT_EQ(std::get<Frame>(first).timestamp_s, 5.0);
  EXPECT_EQ(std::get<Frame>(first).colour.at<cv::Vec3b>(3, 4), cv::Vec3b(10, 20, 30));
  EXPECT_EQ(std::get<Frame>(first).depth.at<std::uint16_t>(3, 4), 1234);
  const NextFrame second = source.next();
  ASSERT_TRUE(std::holds_alternative<Frame>(second));
  EXPECT_DOUBLE_EQ(std::get<Frame>(second).timestamp_s, 5.1);
  ASSERT_TRUE(std::holds_alternative<SourceStop>(source.next()));
}

TEST(RecordedSource, MissingFolderIsNamed) {
  const TemporaryFolder folder;
  EXPECT_EQ(construction_error(folder / "nowhere"),
            "recording folder " + (folder / "nowhere").string() + " does not exist");
}

TEST(RecordedSource, FileInsteadOfFolderIsNamed) {
  const TemporaryFolder folder;
  write_text(folder / "clip.mp4", "");
  EXPECT_EQ(construction_error(folder / "clip.mp4"),
            "recording folder " + (folder / "clip.mp4").string() + " is not a folder");
}

TEST(RecordedSource, BadSequenceYamlNamesFileLineAndKey) {
  const TemporaryFolder folder;
  write_two_frames(folder);
  write_text(folder / "sequence.yaml", kTwoFrames + "exposure: 3\n");
  EXPECT_EQ(construction_error(folder.path()),
            (folder / "sequence.yaml").string() +
                ":6:1: unknown key 'exposure' in sequence.yaml (known keys: intrinsics, "
                "depth_scale_m_per_unit, frame_count, frame_period_s, start_time_s, "
                "timestamps_s, treat_holder)");
}

TEST(RecordedSource, MissingFrameFileIsRefusedAtOnce) {
  const TemporaryFolder folder;
  write_two_frames(folder);
  fs::remove(folder / "depth_000001.png");
  EXPECT_EQ(construction_error(folder.path()),
            "recording " + folder.path().string() +
                " lacks frame file depth_000001.png (sequence.yaml lists 2 frames)");
}

TEST(RecordedSource, ColourOfWrongSizeFailsNamingTheFile) {
  const TemporaryFolder folder;
  write_two_frames(folder);
  cv::imwrite((folder / "colour_000000.png").string(), cv::Mat(12, 16, CV_8UC3));
  EXPECT_EQ(first_frame_failure(folder.path()),
            (folder / "colour_000000.png").string() +
                " declares 16x12 pixels, but sequence.yaml promises 32x24 (not decoded)");
}

// A PNG header can declare a frame of gigabytes in a few bytes (and a few megabytes of
// compressed zeros can fill it): the size is compared before anything is decoded (issue 28).
TEST(RecordedSource, AHugeDeclaredFrameIsRefusedBeforeDecoding) {
  const TemporaryFolder folder;
  write_two_frames(folder);
  std::string header("\x89PNG\r\n\x1a\n\0\0\0\x0dIHDR", 16);
  header += std::string("\0\0\xea\x60\0\0\xea\x60", 8);  // 60000 x 60000
  header += std::string("\x08\x02\0\0\0", 5);
  write_text(folder / "colour_000000.png", header);
  EXPECT_EQ(first_frame_failure(folder.path()),
            (folder / "colour_000000.png").string() +
                " declares 60000x60000 pixels, but sequence.yaml promises 32x24 (not decoded)");
}

TEST(RecordedSource, DepthOfWrongTypeFailsNamingTheFile) {
  const TemporaryFolder folder;
  write_two_frames(folder);
  cv::imwrite((folder / "depth_000000.png").string(), cv::Mat(24, 32, CV_8UC1, cv::Scalar(7)));
  EXPECT_EQ(first_frame_failure(folder.path()),
            (folder / "depth_000000.png").string() +
                " is 32x24 8-bit grey, but sequence.yaml promises 32x24 16-bit single-channel");
}

TEST(RecordedSource, UndecodableFrameFailsNamingTheFile) {
  const TemporaryFolder folder;
  write_two_frames(folder);
  write_text(folder / "colour_000000.png", "not a png");
  EXPECT_EQ(first_frame_failure(folder.path()),
            (folder / "colour_000000.png").string() + " is not a PNG image");
}

TEST(RecordedSource, FrameDeletedDuringPlaybackFailsNamingTheFile) {
  const TemporaryFolder folder;
  write_two_frames(folder);
  RecordedSource source(folder.path());
  fs::remove(folder / "colour_000001.png");
  ASSERT_TRUE(std::holds_alternative<Frame>(source.next()));
  const NextFrame next = source.next();
  ASSERT_TRUE(std::holds_alternative<SourceStop>(next));
  EXPECT_EQ(std::get<SourceStop>(next).kind, SourceStop::Kind::kFailure);
  EXPECT_EQ(std::get<SourceStop>(next).reason,
            (folder / "colour_000001.png").string() + " is missing (deleted during playback?)");
}

}  // namespace
}  // namespace oasis::hw::camera
