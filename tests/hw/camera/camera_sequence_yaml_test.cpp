// sequence.yaml: what a valid file means, that written text reads back exactly, and that each
// kind of mistake is reported with the file, line and column and names the key.
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "camera/camera_error.hpp"
#include "camera/sequence_yaml.hpp"
#include "temporary_folder.hpp"

namespace oasis::hw::camera {
namespace {

using testing::TemporaryFolder;
using testing::write_text;

const std::string kIntrinsics =
    "intrinsics:\n"                    // line 1
    "  fx: 382.6\n"                    // 2
    "  fy: 382.6\n"                    // 3
    "  cx: 319\n"                      // 4
    "  cy: 246.3\n"                    // 5
    "  width: 640\n"                   // 6
    "  height: 480\n"                  // 7
    "depth_scale_m_per_unit: 0.001\n"  // 8
    "frame_count: 3\n";                // 9

SequenceDescription read_text(const TemporaryFolder& folder, const std::string& text) {
  write_text(folder / "sequence.yaml", text);
  return read_sequence_yaml(folder / "sequence.yaml");
}

// The message of the CameraError that reading `text` throws, or "" if it reads.
std::string error_of(const std::string& text) {
  const TemporaryFolder folder;
  try {
    read_text(folder, text);
  } catch (const CameraError& error) {
    // Tests compare the file name, not the random folder around it.
    std::string message = error.what();
    const std::string prefix = folder.path().string() + "/";
    if (message.starts_with(prefix)) message.erase(0, prefix.size());
    return message;
  }
  return "";
}

TEST(SequenceYaml, PeriodGivesEvenlySpacedTimestamps) {
  const TemporaryFolder folder;
  const SequenceDescription description =
      read_text(folder, kIntrinsics + "frame_period_s: 0.5\nstart_time_s: 10\n");
  EXPECT_EQ(description.timestamps_s, (std::vector<double>{10.0, 10.5, 11.0}));
  EXPECT_DOUBLE_EQ(description.intrinsics.fx, 382.6);
  EXPECT_DOUBLE_EQ(description.intrinsics.cy, 246.3);
  EXPECT_EQ(description.intrinsics.width, 640);
  EXPECT_EQ(description.intrinsics.height, 480);
  EXPECT_DOUBLE_EQ(description.depth_scale_m_per_unit, 0.001);
  EXPECT_FALSE(description.has_truth());
}

TEST(SequenceYaml, ListedTimestampsAndTruth) {
  const TemporaryFolder folder;
  const SequenceDescription description =
      read_text(folder, kIntrinsics + "timestamps_s: [0, 0.25, 0.3]\ntreat_holder: [0, 1, 2]\n");
  EXPECT_EQ(description.timestamps_s, (std::vector<double>{0.0, 0.25, 0.3}));
  EXPECT_EQ(description.truth, (std::vector<TreatHolder>{TreatHolder::kNone, TreatHolder::kHuman1,
                                                         TreatHolder::kHuman2}));
}

TEST(SequenceYaml, WrittenTextReadsBackBitForBit) {
  SequenceDescription written;
  written.intrinsics = {613.8 + 1e-9, 1000.0 / 3.0, 317.1, 248.8 + 1e-12, 1280, 720};
  written.depth_scale_m_per_unit = 0.0001;
  for (int i = 0; i < 25; ++i) {  // more than one line of the wrapped list
    written.timestamps_s.push_back(12345.678 + i * (0.1 + 0.2) / 3.0);
    written.truth.push_back(static_cast<TreatHolder>(i % 3));
  }
  const TemporaryFolder folder;
  const SequenceDescription read = read_text(folder, sequence_yaml_text(written));
  EXPECT_EQ(read.intrinsics.fx, written.intrinsics.fx);
  EXPECT_EQ(read.intrinsics.fy, written.intrinsics.fy);
  EXPECT_EQ(read.intrinsics.cx, written.intrinsics.cx);
  EXPECT_EQ(read.intrinsics.cy, written.intrinsics.cy);
  EXPECT_EQ(read.intrinsics.width, 1280);
  EXPECT_EQ(read.intrinsics.height, 720);
  EXPECT_EQ(read.depth_scale_m_per_unit, 0.0001);
  EXPECT_EQ(read.timestamps_s, written.timestamps_s);
  EXPECT_EQ(read.truth, written.truth);
}

TEST(SequenceYaml, EmptyRecordingIsValid) {
  SequenceDescription empty;
  const TemporaryFolder folder;
  EXPECT_EQ(read_text(folder, sequence_yaml_text(empty)).frame_count(), 0u);
}

struct Mistake {
  std::string text;
  std::string message;  // the whole message after the folder
};

TEST(SequenceYaml, EachMistakeIsReportedWithItsPlace) {
  std::string no_fx = kIntrinsics;
  no_fx.erase(no_fx.find("  fx: 382.6\n"), 12);
  const std::vector<Mistake> mistakes = {
      {"", "sequence.yaml: sequence.yaml must be a mapping of keys, not nothing"},
      {"intrinsics: [1, 2\n", "sequence.yaml:2:1: not valid YAML: end of sequence flow not found"},
      {kIntrinsics + "frame_period_s: 0.2\ncolour: bgr\n",
       "sequence.yaml:11:1: unknown key 'colour' in sequence.yaml (known keys: intrinsics, "
       "depth_scale_m_per_unit, frame_count, frame_period_s, start_time_s, timestamps_s, "
       "treat_holder)"},
      {"intrinsics:\n  fz: 1\n",
       "sequence.yaml:2:3: unknown key 'fz' in intrinsics (known keys: fx, fy, cx, cy, width, "
       "height)"},
      {no_fx + "frame_period_s: 0.2\n", "sequence.yaml:2:3: missing key 'fx' in intrinsics"},
      {"frame_count: 1\n", "sequence.yaml:1:1: missing key 'intrinsics' in sequence.yaml"},
      {"intrinsics: 5\n", "sequence.yaml:1:13: intrinsics must be a mapping of keys, not '5'"},
      {kIntrinsics + "frame_period_s: 0.2\nframe_count: 4\n",
       "sequence.yaml:11:1: key 'frame_count' appears twice in sequence.yaml"},
  };
  for (const Mistake& mistake : mistakes)
    EXPECT_EQ(error_of(mistake.text), mistake.message);
}

TEST(SequenceYaml, EachBadValueIsReportedWithItsPlace) {
  const auto with = [](const std::string& from, const std::string& to) {
    std::string text = kIntrinsics + "frame_period_s: 0.2\n";
    text.replace(text.find(from), from.size(), to);
    return text;
  };
  const std::vector<Mistake> mistakes = {
      {with("fx: 382.6", "fx: abc"), "sequence.yaml:2:7: 'fx' must be a number, not 'abc'"},
      {with("fy: 382.6", "fy: [1]"), "sequence.yaml:3:7: 'fy' must be a number, not a sequence"},
      {with("fy: 382.6", "fy: -1"), "sequence.yaml:3:7: 'fy' must be positive, not -1"},
      {with("cx: 319", "cx: .nan"), "sequence.yaml:4:7: 'cx' must be a number, not '.nan'"},
      {with("width: 640", "width: 640.5"),
       "sequence.yaml:6:10: 'width' must be a whole number, not '640.5'"},
      {with("height: 480", "height: 0"),
       "sequence.yaml:7:11: 'height' must be 1 to 65535 pixels, not 0"},
      {with("depth_scale_m_per_unit: 0.001", "depth_scale_m_per_unit: 0"),
       "sequence.yaml:8:25: 'depth_scale_m_per_unit' must be positive, not 0"},
      {with("frame_count: 3", "frame_count: -2"),
       "sequence.yaml:9:14: 'frame_count' must be 0 to 10000000, not -2"},
      {with("frame_period_s: 0.2", "frame_period_s: fast"),
       "sequence.yaml:10:17: 'frame_period_s' must be a number, not 'fast'"},
  };
  for (const Mistake& mistake : mistakes)
    EXPECT_EQ(error_of(mistake.text), mistake.message);
}

TEST(SequenceYaml, EachBadFrameListIsReportedWithItsPlace) {
  const std::vector<Mistake> mistakes = {
      {kIntrinsics, "sequence.yaml:1:1: missing key 'frame_period_s' or 'timestamps_s'"},
      {kIntrinsics + "frame_period_s: 0.2\ntimestamps_s: [0, 1, 2]\n",
       "sequence.yaml:11:15: give 'frame_period_s' or 'timestamps_s', not both"},
      {kIntrinsics + "timestamps_s: [0, 1, 2]\nstart_time_s: 4\n",
       "sequence.yaml:11:15: 'start_time_s' goes with 'frame_period_s' only"},
      {kIntrinsics + "timestamps_s: [0, 1]\n",
       "sequence.yaml:10:15: 'timestamps_s' has 2 entries but frame_count is 3"},
      {kIntrinsics + "timestamps_s: 0.2\n",
       "sequence.yaml:10:15: 'timestamps_s' must be a sequence ([a, b, ...]), not '0.2'"},
      {kIntrinsics + "timestamps_s: [0, 1, 1]\n",
       "sequence.yaml:10:22: 'timestamps_s' must increase, but 1 follows 1"},
      {kIntrinsics + "frame_period_s: 0.2\ntreat_holder: [0, 1]\n",
       "sequence.yaml:11:15: 'treat_holder' has 2 entries but frame_count is 3"},
      {kIntrinsics + "frame_period_s: 0.2\ntreat_holder: [0, 3, 1]\n",
       "sequence.yaml:11:19: 'treat_holder' entries must be 0 (nobody), 1 (human 1) or 2 "
       "(human 2), not 3"},
  };
  for (const Mistake& mistake : mistakes)
    EXPECT_EQ(error_of(mistake.text), mistake.message);
}

TEST(SequenceYaml, MissingFileIsNamed) {
  const TemporaryFolder folder;
  try {
    read_sequence_yaml(folder / "sequence.yaml");
    FAIL() << "no error";
  } catch (const CameraError& error) {
    EXPECT_EQ(std::string(error.what()),
              (folder / "sequence.yaml").string() + ": no such file or directory");
  }
}

// The readers' one rule (common/files/input_file.hpp): a folder or a pipe nobody writes to is
// named as such, never waited on.
TEST(SequenceYaml, AFolderIsNamedAsOne) {
  const TemporaryFolder folder;
  std::filesystem::create_directory(folder / "sequence.yaml");
  try {
    read_sequence_yaml(folder / "sequence.yaml");
    FAIL() << "no error";
  } catch (const CameraError& error) {
    EXPECT_EQ(std::string(error.what()), (folder / "sequence.yaml").string() + ": is a directory");
  }
}

}  // namespace
}  // namespace oasis::hw::camera
