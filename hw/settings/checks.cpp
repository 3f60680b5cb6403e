#include "settings/checks.hpp"

#include <cmath>
#include <set>

#include <yaml-cpp/yaml.h>

#include "settings/schema.hpp"

namespace oasis::hw::settings::detail {

namespace {

constexpr const char* kChannelNames[] = {"hue", "saturation", "value"};
constexpr double kChannelMax[] = {179.0, 255.0, 255.0};

void check_action_speeds(const Go1Settings& settings, std::vector<CrossProblem>& problems) {
  const go1::MotionLimits& limits = settings.link.limits;
  // Why it is an error and not a clamp: the sender would silently drive slower than the speed
  // the spec's dynamics (and so the catalog's policy) assume for this action.
  const std::string why = "; the sender would clamp it and so change what the action means";
  for (const ActionVelocity& entry : settings.loop.actions) {
    const std::string at = "actions." + entry.action + ".";
    const go1::VelocityCommand& v = entry.velocity;
    if (v.forward > limits.max_forward)
      problems.push_back({at + "forward", "limits.max_forward",
                          format_real(v.forward) + " m/s ahead is beyond limits.max_forward (" +
                              format_real(limits.max_forward) + " m/s)" + why});
    if (-v.forward > limits.max_backward)
      problems.push_back({at + "forward", "limits.max_backward",
                          format_real(v.forward) + " m/s is beyond limits.max_backward (" +
                              format_real(limits.max_backward) + " m/s back)" + why});
    if (std::fabs(v.lateral) > limits.max_lateral)
      problems.push_back({at + "lateral", "limits.max_lateral",
                          format_real(v.lateral) + " m/s is beyond limits.max_lateral (" +
                              format_real(limits.max_lateral) + " m/s)" + why});
    if (std::fabs(v.yaw_rate) > limits.max_yaw_rate)
      problems.push_back({at + "yaw_rate", "limits.max_yaw_rate",
                          format_real(v.yaw_rate) + " rad/s is beyond limits.max_yaw_rate (" +
                              format_real(limits.max_yaw_rate) + " rad/s)" + why});
  }
}

// check_settings(): each value must survive the trip the reader makes (written by its codec,
// read back by yaml-cpp and the codec), which applies exactly the reader's ranges.
class Checker {
 public:
  explicit Checker(std::vector<Diagnostic>& out) : out_(out) {}

  template <class Body>
  void section(std::string_view key, std::string_view, Body&& body) {
    prefix_.emplace_back(key);
    body();
    prefix_.pop_back();
  }

  template <class T, class Codec>
  void value(std::string_view key, const T& field, const Codec& codec, std::string_view) {
    const std::string text = codec.format(field);
    T copy = field;
    bool ok = false;
    try {
      ok = codec.parse(YAML::Load(text).Scalar(), copy);
    } catch (const YAML::Exception&) {
      ok = false;
    }
    if (!ok) report(path(key), "expected " + codec.expected() + ", got " + text);
  }

  void bands(std::string_view key, const std::vector<HsvBand>& bands, std::string_view) {
    if (bands.empty()) report(path(key), "expected at least one HSV band");
    for (std::size_t i = 0; i < bands.size(); ++i) {
      const std::string problem = band_problem(bands[i]);
      if (!problem.empty()) report(path(key) + "[" + std::to_string(i) + "]", problem);
    }
  }

  void actions(std::string_view key, const std::vector<ActionVelocity>& actions, std::string_view) {
    if (actions.empty()) report(std::string(key), "expected at least one action");
    std::set<std::string> seen;
    for (const ActionVelocity& entry : actions) {
      const std::string at = std::string(key) + "." + entry.action;
      if (!is_action_name(entry.action))
        report(at, "an action name is a letter or _ followed by letters, digits or _");
      if (!seen.insert(entry.action).second) report(at, "the action is listed twice");
      const go1::VelocityCommand& v = entry.velocity;
      const float components[] = {v.forward, v.lateral, v.yaw_rate};
      for (std::size_t c = 0; c < 3; ++c)
        if (!std::isfinite(components[c]))
          report(at + "." + std::string(kActionComponents[c]), "expected a finite number");
    }
  }

 private:
  std::string path(std::string_view key) const { return dotted_key(prefix_, key); }
  void report(std::string key, std::string message) {
    out_.push_back({0, 0, std::move(key), std::move(message), {}});
  }

  std::vector<Diagnostic>& out_;
  std::vector<std::string> prefix_;
};

}  // namespace

std::vector<CrossProblem> cross_check(const Go1Settings& settings) {
  std::vector<CrossProblem> problems;
  check_action_speeds(settings, problems);

  // The loop feeds the watchdog every keep-alive; one late keep-alive must not stop the robot.
  const auto watchdog_ms = settings.link.watchdog_timeout.count();
  const auto keepalive_ms = settings.loop.keepalive.count();
  if (watchdog_ms < 2 * keepalive_ms)
    problems.push_back({"robot.watchdog_ms", "loop.keepalive_ms",
                        std::to_string(watchdog_ms) + " ms is shorter than two keep-alives (" +
                            std::to_string(keepalive_ms) +
                            " ms each): one late keep-alive would stop the robot"});

  const CameraIntrinsics& k = settings.camera.intrinsics;
  if (!(k.cx < k.width))
    problems.push_back(
        {"camera.intrinsics.cx", "camera.intrinsics.width",
         format_real(k.cx) + " is not inside the image (width " + std::to_string(k.width) + ")"});
  if (!(k.cy < k.height))
    problems.push_back(
        {"camera.intrinsics.cy", "camera.intrinsics.height",
         format_real(k.cy) + " is not inside the image (height " + std::to_string(k.height) + ")"});

  const ReachRegion& reach = settings.perception.reach;
  if (!(reach.x_min_m < reach.x_max_m))
    problems.push_back({"perception.reach.x_max_m", "perception.reach.x_min_m",
                        "x_max_m " + format_real(reach.x_max_m) + " is not above x_min_m " +
                            format_real(reach.x_min_m) + ": the region is empty"});
  if (!(reach.y_min_m < reach.y_max_m))
    problems.push_back({"perception.reach.y_max_m", "perception.reach.y_min_m",
                        "y_max_m " + format_real(reach.y_max_m) + " is not above y_min_m " +
                            format_real(reach.y_min_m) + ": the region is empty"});

  const TagDetectorConfig& tags = settings.perception.tags;
  if (tags.decimate_above_px < tags.upsample_below_px)
    problems.push_back({"perception.tags.decimate_above_px", "perception.tags.upsample_below_px",
                        format_real(tags.decimate_above_px) + " is below upsample_below_px (" +
                            format_real(tags.upsample_below_px) +
                            "): a tag would be upsampled and decimated at once"});
  return problems;
}

std::string band_problem(const HsvBand& band) {
  for (int c = 0; c < 3; ++c) {
    const char* name = kChannelNames[c];
    for (const double value : {band.low[c], band.high[c]}) {
      if (!(value >= 0.0 && value <= kChannelMax[c]) || value != std::floor(value))
        return std::string(name) + " " + format_real(value) + " is not a whole number in 0.." +
               std::to_string(static_cast<int>(kChannelMax[c]));
    }
    if (band.low[c] > band.high[c]) {
      std::string text = "low " + std::string(name) + " " +
                         std::to_string(static_cast<int>(band.low[c])) + " is above high " + name +
                         " " + std::to_string(static_cast<int>(band.high[c])) +
                         ": the band matches nothing";
      if (c == 0) text += " (a hue range across 0 needs two bands, one up to 179 and one from 0)";
      return text;
    }
  }
  return {};
}

bool is_action_name(std::string_view name) {
  if (name.empty()) return false;
  auto letter = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; };
  if (!letter(name.front())) return false;
  for (const char c : name)
    if (!letter(c) && !(c >= '0' && c <= '9')) return false;
  return true;
}

}  // namespace oasis::hw::settings::detail

namespace oasis::hw::settings {

std::vector<Diagnostic> check_settings(const Go1Settings& settings) {
  std::vector<Diagnostic> diagnostics;
  detail::Checker checker(diagnostics);
  detail::describe(checker, settings);
  for (detail::CrossProblem& problem : detail::cross_check(settings))
    diagnostics.push_back({0, 0, std::move(problem.key), std::move(problem.message), {}});
  return diagnostics;
}

}  // namespace oasis::hw::settings
