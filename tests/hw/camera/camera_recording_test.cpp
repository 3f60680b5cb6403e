// Writer and reader together: rendered frames written to a folder come back identical (pixels,
// intrinsics, depth scale, timestamps, truth), the recording ends cleanly, and a folder is
// only a recording once the writer has finished it.
#include <filesystem>
#include <optional>
#include <variant>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include "camera/camera_error.hpp"
#include "camera/recorded_source.hpp"
#include "camera/recording_writer.hpp"
#include "perception/synthetic_renderer.hpp"
#include "temporary_folder.hpp"

namespace oasis::hw::camera {
namespace {

namespace fs = std::filesystem;
using testing::TemporaryFolder;
using testing::write_text;

// Odd values on purpose: they must survive the text of sequence.yaml exactly.
RenderSettings small_camera() {
  RenderSettings settings;
  settings.intrinsics = {191.3 + 1e-9, 1000.0 / 6.0, 159.5, 123.15, 320, 240};
  settings.depth_scale_m_per_unit = 0.0005;
  settings.depth_noise = DepthNoise::realsense_like();  // the noise makes every pixel matter
  return settings;
}

// Frame i: both people in view, the treat with holder i % 3, an irregular timestamp.
std::vector<Frame> rendered_frames(int count) {
  std::vector<Frame> frames;
  for (int i = 0; i < count; ++i) {
    SyntheticScene scene;
    scene.people[0] = PersonPlacement{1.5 + 0.1 * i, 0.4};
    scene.people[1] = PersonPlacement{2.5, -0.5};
    scene.holder = static_cast<TreatHolder>(i % 3);
    scene.seed = static_cast<std::uint64_t>(i + 1);
    frames.push_back(render_scene(scene, small_camera(), 100.0 + i * (0.1 + 0.2) / 3.0));
  }
  return frames;
}

bool same_pixels(const cv::Mat& a, const cv::Mat& b) {
  return a.type() == b.type() && a.size() == b.size() && cv::norm(a, b, cv::NORM_INF) == 0.0;
}

void write_all(const fs::path& folder, const std::vector<Frame>& frames, bool with_truth) {
  RecordingWriter writer(folder);
  for (std::size_t i = 0; i < frames.size(); ++i)
    writer.write(frames[i],
                 with_truth ? std::optional(static_cast<TreatHolder>(i % 3)) : std::nullopt);
  writer.finish();
}

TEST(RecordingRoundTrip, FramesComeBackIdentical) {
  const TemporaryFolder folder;
  const std::vector<Frame> frames = rendered_frames(4);
  write_all(folder.path(), frames, true);

  RecordedSource source(folder.path());
  EXPECT_FALSE(source.truth_of_last_frame().has_value());  // nothing read yet
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const NextFrame next = source.next();
    ASSERT_TRUE(std::holds_alternative<Frame>(next)) << std::get<SourceStop>(next).reason;
    const Frame& read = std::get<Frame>(next);
    EXPECT_TRUE(same_pixels(read.colour, frames[i].colour)) << "colour of frame " << i;
    EXPECT_TRUE(same_pixels(read.depth, frames[i].depth)) << "depth of frame " << i;
    EXPECT_EQ(read.timestamp_s, frames[i].timestamp_s);
    EXPECT_EQ(read.depth_scale_m_per_unit, 0.0005);
    EXPECT_EQ(read.intrinsics.fx, frames[i].intrinsics.fx);
    EXPECT_EQ(read.intrinsics.fy, frames[i].intrinsics.fy);
    EXPECT_EQ(read.intrinsics.cx, frames[i].intrinsics.cx);
    EXPECT_EQ(read.intrinsics.cy, frames[i].intrinsics.cy);
    EXPECT_EQ(read.intrinsics.width, 320);
    EXPECT_EQ(read.intrinsics.height, 240);
    EXPECT_EQ(source.truth_of_last_frame(), std::optional(static_cast<TreatHolder>(i % 3)));
  }
}

TEST(RecordingRoundTrip, EndOfRecordingIsAnEndAndStaysOne) {
  const TemporaryFolder folder;
  write_all(folder.path(), rendered_frames(1), true);
  RecordedSource source(folder.path());
  ASSERT_TRUE(std::holds_alternative<Frame>(source.next()));
  for (int call = 0; call < 2; ++call) {
    const NextFrame next = source.next();
    ASSERT_TRUE(std::holds_alternative<SourceStop>(next));
    EXPECT_EQ(std::get<SourceStop>(next).kind, SourceStop::Kind::kEnd);
    EXPECT_FALSE(source.truth_of_last_frame().has_value());
  }
}

TEST(RecordingRoundTrip, RecordingWithoutTruthHasNone) {
  const TemporaryFolder folder;
  write_all(folder.path(), rendered_frames(2), false);
  RecordedSource source(folder.path());
  EXPECT_FALSE(source.description().has_truth());
  ASSERT_TRUE(std::holds_alternative<Frame>(source.next()));
  EXPECT_FALSE(source.truth_of_last_frame().has_value());
}

TEST(RecordingRoundTrip, EmptyRecordingEndsAtOnce) {
  const TemporaryFolder folder;
  write_all(folder.path(), {}, false);
  RecordedSource source(folder.path());
  const NextFrame next = source.next();
  ASSERT_TRUE(std::holds_alternative<SourceStop>(next));
  EXPECT_EQ(std::get<SourceStop>(next).kind, SourceStop::Kind::kEnd);
}

TEST(RecordingRoundTrip, UnfinishedRecordingIsRefused) {
  const TemporaryFolder folder;
  RecordingWriter writer(folder.path());
  writer.write(rendered_frames(1)[0]);
  EXPECT_FALSE(fs::exists(folder / "sequence.yaml"));
  try {
    RecordedSource source(folder.path());
    FAIL() << "an unfinished recording was accepted";
  } catch (const CameraError& error) {
    EXPECT_EQ(std::string(error.what()),
              "recording folder " + folder.path().string() +
                  " has no sequence.yaml (the writer adds it last: was the recording finished?)");
  }
  writer.finish();
  EXPECT_NO_THROW(RecordedSource source(folder.path()));
  EXPECT_FALSE(fs::exists(folder / "sequence.yaml.tmp"));
}

TEST(RecordingWriter, RefusesAFolderThatHoldsFiles) {
  const TemporaryFolder folder;
  write_text(folder / "notes.txt", "mine");
  try {
    RecordingWriter writer(folder.path());
    FAIL() << "a non-empty folder was accepted";
  } catch (const CameraError& error) {
    EXPECT_EQ(std::string(error.what()),
              "recording folder " + folder.path().string() +
                  " is not empty; choose an empty folder or ask to replace the recording");
  }
  EXPECT_THROW(RecordingWriter(folder / "notes.txt"), CameraError);  // a file, not a folder
}

TEST(RecordingWriter, ReplaceDeletesOnlyTheEarlierRecording) {
  const TemporaryFolder folder;
  write_all(folder.path(), rendered_frames(3), true);
  write_text(folder / "notes.txt", "mine");
  {
    RecordingWriter writer(folder.path(), ExistingFolder::kReplace);
    EXPECT_FALSE(fs::exists(folder / "sequence.yaml"));  // no longer a recording while replaced
    writer.write(rendered_frames(1)[0]);
    writer.finish();
  }
  EXPECT_TRUE(fs::exists(folder / "notes.txt"));
  EXPECT_FALSE(fs::exists(folder / "colour_000002.png"));
  EXPECT_EQ(RecordedSource(folder.path()).description().frame_count(), 1u);
}

TEST(RecordingWriter, CreatesMissingFolders) {
  const TemporaryFolder folder;
  write_all(folder / "day1/run2", rendered_frames(1), false);
  EXPECT_EQ(RecordedSource(folder / "day1/run2").description().frame_count(), 1u);
}

TEST(RecordingWriter, RefusesFramesThatDoNotFit) {
  const TemporaryFolder folder;
  RecordingWriter writer(folder.path());
  const std::vector<Frame> frames = rendered_frames(2);
  writer.write(frames[0], TreatHolder::kHuman1);

  Frame other_camera = frames[1];
  other_camera.intrinsics.fx += 1.0;
  EXPECT_THROW(writer.write(other_camera, TreatHolder::kNone), CameraError);
  Frame same_time = frames[1];
  same_time.timestamp_s = frames[0].timestamp_s;
  EXPECT_THROW(writer.write(same_time, TreatHolder::kNone), CameraError);
  EXPECT_THROW(writer.write(frames[1]), CameraError);  // truth missing after frame 0 had it
  Frame grey = frames[1];
  grey.colour = cv::Mat(240, 320, CV_8UC1, cv::Scalar(0));
  EXPECT_THROW(writer.write(grey, TreatHolder::kNone), CameraError);
  Frame small_depth = frames[1];
  small_depth.depth = cv::Mat(120, 160, CV_16UC1, cv::Scalar(0));
  EXPECT_THROW(writer.write(small_depth, TreatHolder::kNone), CameraError);

  EXPECT_EQ(writer.frames_written(), 1u);  // refused frames leave nothing behind
  writer.write(frames[1], TreatHolder::kNone);
  writer.finish();
  EXPECT_THROW(writer.write(frames[1], TreatHolder::kNone), CameraError);
}

TEST(RecordingWriter, SequenceYamlIsReadable) {
  const TemporaryFolder folder;
  write_all(folder.path(), rendered_frames(2), true);
  std::ifstream file(folder / "sequence.yaml");
  const std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("frame_count: 2\n"), std::string::npos) << text;
  EXPECT_NE(text.find("treat_holder: [0, 1]\n"), std::string::npos) << text;
  EXPECT_NE(text.find("  width: 320\n"), std::string::npos) << text;
}

}  // namespace
}  // namespace oasis::hw::camera
