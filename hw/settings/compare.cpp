// differing_keys(): both settings are flattened to (key path, value text) pairs through the
// codecs of schema.hpp; a codec writes the shortest text that reads back to the same value,
// so two values are equal exactly when their texts are.

#include <map>

#include "settings/schema.hpp"
#include "yaml_schema/schema_flattener.hpp"

namespace oasis::hw::settings {

namespace detail {
namespace {

// The settings' entries beyond plain values: colour bands and the action table.
class Flattener : public SchemaFlattener {
 public:
  void bands(std::string_view key, const std::vector<HsvBand>& bands, std::string_view) {
    std::string text;
    for (const HsvBand& band : bands)
      for (const cv::Scalar* hsv : {&band.low, &band.high})
        for (int c = 0; c < 3; ++c)
          text += format_real((*hsv)[c]) + " ";
    add(path(key), text);
  }

  void actions(std::string_view key, const std::vector<ActionVelocity>& actions, std::string_view) {
    if (actions.empty()) add(path(key), "{}");
    for (const ActionVelocity& entry : actions) {
      const std::string at = path(key) + "." + entry.action + ".";
      add(at + "forward", format_real(entry.velocity.forward));
      add(at + "lateral", format_real(entry.velocity.lateral));
      add(at + "yaw_rate", format_real(entry.velocity.yaw_rate));
    }
  }
};

std::vector<std::pair<std::string, std::string>> flatten(const Go1Settings& settings) {
  Flattener flattener;
  describe(flattener, settings);
  return flattener.pairs;
}

}  // namespace
}  // namespace detail

std::vector<std::string> differing_keys(const Go1Settings& a, const Go1Settings& b) {
  const auto flat_a = detail::flatten(a);
  const auto flat_b = detail::flatten(b);
  const std::map<std::string, std::string> map_a(flat_a.begin(), flat_a.end());
  const std::map<std::string, std::string> map_b(flat_b.begin(), flat_b.end());
  std::vector<std::string> keys;
  for (const auto& [key, text] : flat_a) {
    const auto other = map_b.find(key);
    if (other == map_b.end() || other->second != text) keys.push_back(key);
  }
  for (const auto& [key, text] : flat_b)
    if (map_a.find(key) == map_a.end()) keys.push_back(key);
  return keys;
}

}  // namespace oasis::hw::settings
