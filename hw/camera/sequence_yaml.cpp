#include "camera/sequence_yaml.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <optional>
#include <span>
#include <string_view>
#include <utility>

#include <yaml-cpp/yaml.h>

#include "camera/camera_error.hpp"
#include "camera/recording_layout.hpp"
#include "files/input_file.hpp"

namespace oasis::hw::camera {

namespace {

namespace fs = std::filesystem;

constexpr std::array<std::string_view, 7> kTopKeys = {
    "intrinsics",   "depth_scale_m_per_unit", "frame_count", "frame_period_s",
    "start_time_s", "timestamps_s",           "treat_holder"};
constexpr std::array<std::string_view, 6> kIntrinsicsKeys = {"fx", "fy",    "cx",
                                                             "cy", "width", "height"};

// Far more than any recording (a day at 30 frames/s is 2.6 million); stops a typo from
// expanding a frame period into an enormous list.
constexpr long long kMaxFrameCount = 10'000'000;
// sequence.yaml is a page of numbers; anything this large is the wrong file.
constexpr std::size_t kMaxSequenceBytes = std::size_t{1} << 20;

std::string joined(std::span<const std::string_view> words) {
  std::string text;
  for (const std::string_view word : words)
    text += (text.empty() ? "" : ", ") + std::string(word);
  return text;
}

// How a value looks, for "must be a number, not ..." messages.
std::string shown(const YAML::Node& node) {
  if (node.IsMap()) return "a mapping";
  if (node.IsSequence()) return "a sequence";
  if (node.IsNull()) return "nothing";
  return "'" + node.Scalar() + "'";
}

// The shortest text that reads back as exactly this double.
std::string exact(double value) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, value).ptr;
  return std::string(text, end);
}

// A mapping whose keys were checked against a list: each known key at most once.
struct Mapping {
  YAML::Node node;
  std::string name;  // for messages: "sequence.yaml", "intrinsics"
  std::vector<std::pair<std::string, YAML::Node>> entries;
};

// Reads one sequence.yaml; every complaint is prefixed with the file and the node's position.
class SequenceReader {
 public:
  explicit SequenceReader(fs::path file) : file_(std::move(file)) {}

  SequenceDescription read() const;

 private:
  YAML::Node load() const;
  [[noreturn]] void fail(const YAML::Mark& mark, const std::string& message) const;
  [[noreturn]] void fail(const YAML::Node& node, const std::string& message) const {
    fail(node.Mark(), message);
  }
  Mapping mapping(const YAML::Node& node, std::string name,
                  std::span<const std::string_view> known_keys) const;
  std::optional<YAML::Node> find(const Mapping& mapping, std::string_view key) const;
  YAML::Node require(const Mapping& mapping, std::string_view key) const;

  double number(const YAML::Node& node, std::string_view key) const;
  double positive(const YAML::Node& node, std::string_view key) const;
  long long whole_number(const YAML::Node& node, std::string_view key) const;
  YAML::Node list(const YAML::Node& node, std::string_view key, std::size_t frame_count) const;

  CameraIntrinsics intrinsics(const YAML::Node& node) const;
  std::vector<double> timestamps(const Mapping& top, std::size_t frame_count) const;
  std::vector<TreatHolder> truth(const YAML::Node& node, std::size_t frame_count) const;

  fs::path file_;
};

void SequenceReader::fail(const YAML::Mark& mark, const std::string& message) const {
  std::string where = file_.string() + ":";
  // yaml-cpp counts lines and columns from 0; editors and compilers from 1.
  if (!mark.is_null())
    where += std::to_string(mark.line + 1) + ":" + std::to_string(mark.column + 1) + ":";
  throw CameraError(where + " " + message);
}

YAML::Node SequenceReader::load() const {
  // The readers' one rule (common/files/input_file.hpp): no directory, device or silent pipe.
  std::string reason;
  const std::optional<std::string> text =
      files::read_input(file_.string(), kMaxSequenceBytes, reason);
  if (!text) throw CameraError(file_.string() + ": " + reason);
  try {
    return YAML::Load(*text);
  } catch (const YAML::ParserException& error) {
    fail(error.mark, "not valid YAML: " + error.msg);
  }
}

Mapping SequenceReader::mapping(const YAML::Node& node, std::string name,
                                std::span<const std::string_view> known_keys) const {
  if (!node.IsMap()) fail(node, name + " must be a mapping of keys, not " + shown(node));
  Mapping result{node, std::move(name), {}};
  for (const auto& entry : node) {
    const std::string key = entry.first.Scalar();
    if (std::find(known_keys.begin(), known_keys.end(), key) == known_keys.end())
      fail(entry.first, "unknown key '" + key + "' in " + result.name +
                            " (known keys: " + joined(known_keys) + ")");
    if (find(result, key)) fail(entry.first, "key '" + key + "' appears twice in " + result.name);
    result.entries.emplace_back(key, entry.second);
  }
  return result;
}

std::optional<YAML::Node> SequenceReader::find(const Mapping& mapping, std::string_view key) const {
  for (const auto& [name, value] : mapping.entries)
    if (name == key) return value;
  return std::nullopt;
}

YAML::Node SequenceReader::require(const Mapping& mapping, std::string_view key) const {
  if (auto value = find(mapping, key)) return *value;
  fail(mapping.node, "missing key '" + std::string(key) + "' in " + mapping.name);
}

double SequenceReader::number(const YAML::Node& node, std::string_view key) const {
  double value = 0.0;
  if (!node.IsScalar() || !YAML::convert<double>::decode(node, value) || !std::isfinite(value))
    fail(node, "'" + std::string(key) + "' must be a number, not " + shown(node));
  return value;
}

double SequenceReader::positive(const YAML::Node& node, std::string_view key) const {
  const double value = number(node, key);
  if (value <= 0.0) fail(node, "'" + std::string(key) + "' must be positive, not " + node.Scalar());
  return value;
}

long long SequenceReader::whole_number(const YAML::Node& node, std::string_view key) const {
  long long value = 0;
  if (!node.IsScalar() || !YAML::convert<long long>::decode(node, value))
    fail(node, "'" + std::string(key) + "' must be a whole number, not " + shown(node));
  return value;
}

// A sequence with one entry per frame.
YAML::Node SequenceReader::list(const YAML::Node& node, std::string_view key,
                                std::size_t frame_count) const {
  if (!node.IsSequence())
    fail(node, "'" + std::string(key) + "' must be a sequence ([a, b, ...]), not " + shown(node));
  if (node.size() != frame_count)
    fail(node, "'" + std::string(key) + "' has " + std::to_string(node.size()) +
                   " entries but frame_count is " + std::to_string(frame_count));
  return node;
}

CameraIntrinsics SequenceReader::intrinsics(const YAML::Node& node) const {
  const Mapping keys = mapping(node, "intrinsics", kIntrinsicsKeys);
  CameraIntrinsics result;
  result.fx = positive(require(keys, "fx"), "fx");
  result.fy = positive(require(keys, "fy"), "fy");
  result.cx = number(require(keys, "cx"), "cx");
  result.cy = number(require(keys, "cy"), "cy");
  for (const std::string_view key : {"width", "height"}) {
    const YAML::Node value = require(keys, key);
    const long long pixels = whole_number(value, key);
    if (pixels < 1 || pixels > 65535)
      fail(value, "'" + std::string(key) + "' must be 1 to 65535 pixels, not " + value.Scalar());
    (key == "width" ? result.width : result.height) = static_cast<int>(pixels);
  }
  return result;
}

// Either a period (frame i at start_time_s + i * frame_period_s) or one timestamp per frame.
std::vector<double> SequenceReader::timestamps(const Mapping& top, std::size_t frame_count) const {
  const std::optional<YAML::Node> period = find(top, "frame_period_s");
  const std::optional<YAML::Node> listed = find(top, "timestamps_s");
  const std::optional<YAML::Node> start = find(top, "start_time_s");
  if (period && listed) fail(*listed, "give 'frame_period_s' or 'timestamps_s', not both");
  if (!period && !listed) fail(top.node, "missing key 'frame_period_s' or 'timestamps_s'");
  if (listed && start) fail(*start, "'start_time_s' goes with 'frame_period_s' only");
  std::vector<double> result;
  if (period) {
    const double step = positive(*period, "frame_period_s");
    const double first = start ? number(*start, "start_time_s") : 0.0;
    for (std::size_t i = 0; i < frame_count; ++i)
      result.push_back(first + static_cast<double>(i) * step);
    return result;
  }
  for (const YAML::Node& entry : list(*listed, "timestamps_s", frame_count)) {
    const double time = number(entry, "timestamps_s");
    if (!result.empty() && time <= result.back())
      fail(entry, "'timestamps_s' must increase, but " + entry.Scalar() + " follows " +
                      exact(result.back()));
    result.push_back(time);
  }
  return result;
}

std::vector<TreatHolder> SequenceReader::truth(const YAML::Node& node,
                                               std::size_t frame_count) const {
  std::vector<TreatHolder> result;
  for (const YAML::Node& entry : list(node, "treat_holder", frame_count)) {
    const long long holder = whole_number(entry, "treat_holder");
    if (holder < 0 || holder > 2)
      fail(entry, "'treat_holder' entries must be 0 (nobody), 1 (human 1) or 2 (human 2), not " +
                      entry.Scalar());
    result.push_back(static_cast<TreatHolder>(holder));
  }
  return result;
}

SequenceDescription SequenceReader::read() const {
  const Mapping top = mapping(load(), std::string(kSequenceFileName), kTopKeys);
  SequenceDescription description;
  description.intrinsics = intrinsics(require(top, "intrinsics"));
  description.depth_scale_m_per_unit =
      positive(require(top, "depth_scale_m_per_unit"), "depth_scale_m_per_unit");
  const YAML::Node count_node = require(top, "frame_count");
  const long long count = whole_number(count_node, "frame_count");
  if (count < 0 || count > kMaxFrameCount)
    fail(count_node, "'frame_count' must be 0 to " + std::to_string(kMaxFrameCount) + ", not " +
                         count_node.Scalar());
  const auto frame_count = static_cast<std::size_t>(count);
  description.timestamps_s = timestamps(top, frame_count);
  if (const auto holders = find(top, "treat_holder"))
    description.truth = truth(*holders, frame_count);
  return description;
}

// A flow sequence, ten entries per line so long recordings stay readable.
template <typename Values, typename Format>
std::string flow_list(const Values& values, Format format) {
  std::string text = "[";
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i > 0) text += (i % 10 == 0) ? ",\n  " : ", ";
    text += format(values[i]);
  }
  return text + "]";
}

}  // namespace

SequenceDescription read_sequence_yaml(const std::filesystem::path& file) {
  return SequenceReader(file).read();
}

std::string sequence_yaml_text(const SequenceDescription& description) {
  const CameraIntrinsics& k = description.intrinsics;
  std::string text =
      "# An oasis camera recording (hw/camera/README.md). Frame i is colour_<i>.png (8-bit BGR)\n"
      "# and depth_<i>.png (16-bit; metres = value * depth_scale_m_per_unit), i as 000000, ...\n";
  text += "intrinsics:\n  fx: " + exact(k.fx) + "\n  fy: " + exact(k.fy) +
          "\n  cx: " + exact(k.cx) + "\n  cy: " + exact(k.cy) +
          "\n  width: " + std::to_string(k.width) + "\n  height: " + std::to_string(k.height) +
          "\n";
  text += "depth_scale_m_per_unit: " + exact(description.depth_scale_m_per_unit) + "\n";
  text += "frame_count: " + std::to_string(description.frame_count()) + "\n";
  text += "timestamps_s: " + flow_list(description.timestamps_s, exact) + "\n";
  if (description.has_truth()) {
    text += "# who holds the treat in each frame: 0 nobody, 1 human 1 (red), 2 human 2 (yellow)\n";
    text += "treat_holder: " +
            flow_list(description.truth,
                      [](TreatHolder holder) { return std::to_string(static_cast<int>(holder)); }) +
            "\n";
  }
  return text;
}

}  // namespace oasis::hw::camera
