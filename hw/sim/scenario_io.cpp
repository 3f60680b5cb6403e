// load_scenario(), parse_scenario(), scenario_to_yaml(), differing_keys(): the schema reader,
// writer and flattener of hw/yaml_schema walk scenario_schema.hpp.

#include <map>
#include <utility>

#include "sim/scenario_schema.hpp"
#include "yaml_schema/schema_flattener.hpp"
#include "yaml_schema/schema_reader.hpp"
#include "yaml_schema/schema_writer.hpp"

namespace oasis::hw::sim {

namespace detail {
namespace {

using yaml_schema::CrossProblem;

constexpr std::string_view kBanner =
    "# The hallway scenario of `oasis-go1 sim` (hw/sim/README.md), written by\n"
    "# scenario_to_yaml() (`oasis-go1 sim --print-scenario`). Every key is here with its\n"
    "# meaning; a file may hold only the keys that differ, and an unknown key is an error.\n"
    "# The defaults are hw/config/hallway.yaml: regenerate it from the code, not by hand.\n";

void check_order(double low, double high, const std::string& low_key, const std::string& high_key,
                 std::vector<CrossProblem>& problems) {
  if (low <= high) return;
  problems.push_back({low_key, high_key,
                      yaml_schema::format_real(low) + " is above " + high_key + " (" +
                          yaml_schema::format_real(high) + ")"});
}

}  // namespace

std::vector<CrossProblem> cross_check(const HallwayScenario& s) {
  std::vector<CrossProblem> problems;
  check_order(s.holder.start_min_m, s.holder.start_max_m, "holder.start_min_m",
              "holder.start_max_m", problems);
  check_order(s.holder.wait_beyond_m, s.holder.return_beyond_m, "holder.wait_beyond_m",
              "holder.return_beyond_m", problems);
  check_order(s.holder.walk_speed_min_m_s, s.holder.walk_speed_max_m_s, "holder.walk_speed_min_m_s",
              "holder.walk_speed_max_m_s", problems);
  check_order(s.other.speed_min_m_s, s.other.speed_max_m_s, "other.speed_min_m_s",
              "other.speed_max_m_s", problems);
  check_order(s.other.cross_min_m, s.other.cross_max_m, "other.cross_min_m", "other.cross_max_m",
              problems);
  check_order(s.other.away_min_s, s.other.away_max_s, "other.away_min_s", "other.away_max_s",
              problems);
  check_order(s.treat.hand_offs_min, s.treat.hand_offs_max, "treat.hand_offs_min",
              "treat.hand_offs_max", problems);
  check_order(s.treat.hide_min_s, s.treat.hide_max_s, "treat.hide_min_s", "treat.hide_max_s",
              problems);
  check_order(s.camera.min_range_m, s.camera.max_range_m, "camera.min_range_m",
              "camera.max_range_m", problems);
  const double weights =
      s.other.wander_weight + s.other.cross_weight + s.other.zigzag_weight + s.other.leave_weight;
  if (!(weights > 0.0))
    problems.push_back({"other.wander_weight", "", "the four behaviour weights are all 0"});
  if (2.0 * s.hallway.wall_margin_m >= s.hallway.width_m)
    problems.push_back({"hallway.wall_margin_m", "hallway.width_m",
                        "the margins leave no room between the walls"});
  // The latest schedule the hand-off rules allow must fit in the trial.
  const double needed =
      s.treat.first_after_s + s.treat.last_before_s +
      (s.treat.hand_offs_max > 0 ? s.treat.hand_offs_max - 1 : 0) * s.treat.min_gap_s;
  if (s.treat.hand_offs_max > 0 && needed > s.trial.duration_s)
    problems.push_back({"treat.hand_offs_max", "trial.duration_s",
                        std::to_string(s.treat.hand_offs_max) + " hand-offs need " +
                            yaml_schema::format_real(needed) +
                            " s (first_after_s + last_before_s + gaps), more than the trial"});
  return problems;
}

}  // namespace detail

HallwayScenario parse_scenario(std::string_view yaml_text, std::string_view file_name) {
  HallwayScenario scenario;
  yaml_schema::parse_with_schema(
      yaml_text, file_name, scenario,
      [](auto& visitor, auto& values) { detail::describe(visitor, values); },
      [](const HallwayScenario& values) { return detail::cross_check(values); },
      "trial:, hallway:, holder:, other:, treat:, camera:");
  return scenario;
}

HallwayScenario load_scenario(const std::filesystem::path& file) {
  return parse_scenario(yaml_schema::read_yaml_file(file), file.string());
}

std::string scenario_to_yaml(const HallwayScenario& scenario) {
  yaml_schema::Writer writer{std::string(detail::kBanner)};
  detail::describe(writer, scenario);
  return writer.text();
}

std::vector<std::string> differing_keys(const HallwayScenario& a, const HallwayScenario& b) {
  yaml_schema::SchemaFlattener flat_a, flat_b;
  detail::describe(flat_a, a);
  detail::describe(flat_b, b);
  std::vector<std::string> keys;
  for (std::size_t k = 0; k < flat_a.pairs.size(); ++k)  // same schema: same keys, same order
    if (flat_a.pairs[k].second != flat_b.pairs[k].second) keys.push_back(flat_a.pairs[k].first);
  return keys;
}

}  // namespace oasis::hw::sim
