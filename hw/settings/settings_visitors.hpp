// The schema engine's visitors (hw/yaml_schema/) taught the Go1 settings' two entries that are
// not scalars: the colour bands of a shirt (bands(), a list of HSV bands) and the action
// table (actions(), action name -> velocity). schema.hpp's describe() calls them; the reader,
// the writer and the key lister here, the checks (checks.cpp) and the comparison
// (compare.cpp) each handle them.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "settings/checks.hpp"
#include "settings/go1_codecs.hpp"
#include "yaml_schema/schema_reader.hpp"
#include "yaml_schema/schema_writer.hpp"

namespace oasis::hw::settings::detail {

// Every key path of the settings, bands and actions included.
class SettingsKeyLister : public KeyLister {
 public:
  template <class T>
  void bands(std::string_view key, const T&, std::string_view) {
    add(key);
  }
  template <class T>
  void actions(std::string_view key, const T&, std::string_view) {
    add(key);
  }
};

// Reads the bands (each checked by band_problem()) and the action table (its keys are data:
// every action name is accepted).
class SettingsReader : public Reader {
 public:
  using Reader::Reader;

  void bands(std::string_view key, std::vector<HsvBand>& field, std::string_view) {
    const std::optional<Entry> entry = take(key);
    if (!entry) return;
    const std::string path = path_of(key);
    const YAML::Node& node = entry->value;
    if (!node.IsSequence() || node.size() == 0) {
      error(at(*entry), path,
            "expected a list of HSV bands such as [{low: [0, 120, 70], high: [10, 255, 255]}], "
            "got " +
                what_node_is(node));
      return;
    }
    std::vector<HsvBand> bands;
    bool all_ok = true;
    std::size_t index = 0;
    for (const YAML::Node& item : node) {
      const std::string item_path = path + "[" + std::to_string(index++) + "]";
      HsvBand band;
      const bool ok = read_band(item_path, item, band);
      all_ok = all_ok && ok;
      bands.push_back(band);
    }
    if (all_ok) field = std::move(bands);
  }

  void actions(std::string_view key, std::vector<ActionVelocity>& field, std::string_view) {
    const std::optional<Entry> entry = take(key);
    if (!entry) return;
    const std::string path = path_of(key);
    if (!open(path, entry->value)) return;
    std::vector<ActionVelocity> actions;
    bool all_ok = true;
    for (const Entry& action : accept_every_key()) {
      ActionVelocity parsed{action.key, {}};
      const bool ok = read_action(path + "." + action.key, action, parsed);
      all_ok = all_ok && ok;
      actions.push_back(parsed);
    }
    close();
    if (all_ok && actions.empty()) {
      error(at(*entry), path,
            "expected at least one action: a mapping of action name -> {forward, lateral, "
            "yaw_rate}");
    } else if (all_ok) {
      field = std::move(actions);
    }
  }

 private:
  bool read_band(const std::string& path, const YAML::Node& item, HsvBand& band) {
    if (!open(path, item)) return false;
    bool ok = true;
    for (const std::string_view bound : {"low", "high"}) {
      const std::optional<Entry> entry = take(bound);
      if (!entry) {
        error(item.Mark(), path,
              "missing " + std::string(bound) + ": a band is {low: [h, s, v], high: [h, s, v]}");
        ok = false;
      } else if (!read_hsv(path + "." + std::string(bound), *entry,
                           bound == "low" ? band.low : band.high)) {
        ok = false;
      }
    }
    close();
    if (!ok) return false;
    const std::string problem = band_problem(band);
    if (problem.empty()) return true;
    error(item.Mark(), path, problem);
    return false;
  }

  bool read_hsv(const std::string& path, const Entry& entry, cv::Scalar& hsv) {
    const YAML::Node& node = entry.value;
    if (!node.IsSequence() || node.size() != 3) {
      error(at(entry), path,
            "expected [hue, saturation, value] such as [0, 120, 70], got " + what_node_is(node));
      return false;
    }
    constexpr std::string_view kChannels[] = {"a hue", "a saturation", "a value"};
    constexpr int kMax[] = {179, 255, 255};
    bool ok = true;
    for (int c = 0; c < 3; ++c) {
      const YAML::Node element = node[static_cast<std::size_t>(c)];
      const IntegerCodec<int> codec{0, kMax[c]};
      int channel = 0;
      if (element.IsScalar() && codec.parse(element.Scalar(), channel)) {
        hsv[c] = channel;
        continue;
      }
      error(element.Mark(), path,
            "expected " + std::string(kChannels[c]) + " in 0.." + std::to_string(kMax[c]) +
                ", got " + what_node_is(element));
      ok = false;
    }
    return ok;
  }

  bool read_action(const std::string& path, const Entry& entry, ActionVelocity& action) {
    if (!is_action_name(entry.key)) {
      error(entry.key_mark, path,
            "an action name is a letter or _ followed by letters, digits or _, as in the spec");
      return false;
    }
    if (!open(path, entry.value, /*null_is_empty=*/true)) return false;
    float* components[] = {&action.velocity.forward, &action.velocity.lateral,
                           &action.velocity.yaw_rate};
    bool ok = true;
    for (std::size_t c = 0; c < 3; ++c) {
      const std::optional<Entry> component = take(kActionComponents[c]);
      if (component && !read_scalar(path_of(kActionComponents[c]), *component, *components[c],
                                    RealCodec<float>{}))
        ok = false;
    }
    close();
    return ok;
  }
};

// What parse_with_schema() reads the settings with.
struct SettingsVisitors {
  using Lister = SettingsKeyLister;
  using Reader = SettingsReader;
};

inline std::string channel_text(double value) {
  if (value == std::floor(value) && std::fabs(value) < 1e9)
    return std::to_string(static_cast<long long>(value));
  return format_real(value);
}

inline std::string hsv_text(const cv::Scalar& hsv) {
  return "[" + channel_text(hsv[0]) + ", " + channel_text(hsv[1]) + ", " + channel_text(hsv[2]) +
         "]";
}

// Writes a band list as flow mappings under its key, the action table as one aligned line per
// action.
class SettingsWriter : public Writer {
 public:
  using Writer::Writer;

  void bands(std::string_view key, const std::vector<HsvBand>& bands, std::string_view comment) {
    add(std::string(key) + ":", comment);
    nested([&] {
      for (const HsvBand& band : bands)
        add("- {low: " + hsv_text(band.low) + ", high: " + hsv_text(band.high) + "}", "");
    });
  }

  void actions(std::string_view key, const std::vector<ActionVelocity>& actions,
               std::string_view comment) {
    begin_item();
    comment_block(comment);
    add(std::string(key) + ":", "");
    std::size_t width = 0;
    for (const ActionVelocity& entry : actions)
      width = std::max(width, yaml_string(entry.action).size());
    nested([&] {
      for (const ActionVelocity& entry : actions) {
        std::string name = yaml_string(entry.action) + ":";
        name.resize(width + 1, ' ');
        const go1::VelocityCommand& v = entry.velocity;
        add(name + " {forward: " + format_real(v.forward) + ", lateral: " + format_real(v.lateral) +
                ", yaw_rate: " + format_real(v.yaw_rate) + "}",
            "");
      }
    });
  }
};

}  // namespace oasis::hw::settings::detail
