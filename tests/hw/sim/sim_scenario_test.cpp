// The hallway scenario file: the shipped hw/config/hallway.yaml against the code's defaults,
// partial files, and errors in the compiler's format (FILE:LINE:COL: error: KEY: MESSAGE).
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "sim/scenario.hpp"
#include "yaml_schema/schema_reader.hpp"
#include "yaml_schema/settings_error.hpp"

namespace oasis::hw::sim {
namespace {

using Keys = std::vector<std::string>;

// The first error's text, or "" when the text parses.
std::string error_of(const std::string& yaml) {
  try {
    parse_scenario(yaml, "hallway.yaml");
  } catch (const yaml_schema::SettingsError& e) {
    return e.what();
  }
  return "";
}

TEST(SimScenario, HallwayYamlLoadsToTheDefaults) {
  EXPECT_EQ(differing_keys(load_scenario(OASIS_SHIPPED_HALLWAY_YAML), HallwayScenario{}), Keys{});
}

TEST(SimScenario, HallwayYamlIsTheDefaultsPrintedWithEveryKey) {
  const std::string expected = scenario_to_yaml(HallwayScenario{});
  if (yaml_schema::read_yaml_file(OASIS_SHIPPED_HALLWAY_YAML) == expected) return;
  const std::string fresh = std::filesystem::absolute("hallway.yaml.expected").string();
  std::ofstream(fresh, std::ios::binary) << expected;
  ADD_FAILURE() << OASIS_SHIPPED_HALLWAY_YAML << " is not scenario_to_yaml(HallwayScenario{}).\n"
                << "If the code's defaults and comments are right, refresh the file with\n"
                << "  cp " << fresh << " " << OASIS_SHIPPED_HALLWAY_YAML;
}

TEST(SimScenario, APartialFileKeepsTheOtherDefaults) {
  const HallwayScenario scenario =
      parse_scenario("treat: {hand_offs_max: 2}\ncamera:\n  depth_noise_c_per_m: 0.01\n", "x");
  EXPECT_EQ(differing_keys(scenario, HallwayScenario{}),
            (Keys{"treat.hand_offs_max", "camera.depth_noise_c_per_m"}));
  EXPECT_EQ(scenario.camera.depth_noise.quadratic, 0.01);
}

TEST(SimScenario, ARoundTripKeepsEveryValue) {
  HallwayScenario changed;
  changed.holder.mean_walk_s = 1.0 / 3.0;
  changed.other.leave_weight = 0.0;
  changed.treat.hand_offs_min = 2;
  EXPECT_EQ(differing_keys(parse_scenario(scenario_to_yaml(changed), "x"), changed), Keys{});
}

TEST(SimScenario, ErrorsNameFileLineColumnAndKey) {
  EXPECT_NE(error_of("trial:\n  duration_s: -1\n")
                .find("hallway.yaml:2:15: error: trial.duration_s: expected a number in"),
            std::string::npos);
  EXPECT_NE(error_of("holder:\n  mean_wlak_s: 2\n")
                .find("hallway.yaml:2:3: error: holder.mean_wlak_s: unknown key; did you mean "
                      "\"mean_walk_s\"?"),
            std::string::npos);
  EXPECT_NE(error_of("camera:\n  miss_probability: 1.5\n").find("camera.miss_probability"),
            std::string::npos);
}

TEST(SimScenario, ChecksAcrossKeys) {
  EXPECT_NE(error_of("treat:\n  hand_offs_min: 3\n  hand_offs_max: 2\n")
                .find("hallway.yaml:2:18: error: treat.hand_offs_min: 3.0 is above "
                      "treat.hand_offs_max"),
            std::string::npos);
  EXPECT_NE(error_of("treat: {hand_offs_max: 9}\n").find("9 hand-offs need"), std::string::npos);
  EXPECT_NE(error_of("other: {wander_weight: 0, cross_weight: 0, zigzag_weight: 0, "
                     "leave_weight: 0}\n")
                .find("all 0"),
            std::string::npos);
}

}  // namespace
}  // namespace oasis::hw::sim
