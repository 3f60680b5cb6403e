// The hallway scenario file of oasis-go1 sim (hw/sim/scenario.hpp, hw/config/hallway.yaml):
// any text either gives a scenario whose keys pass the checks across keys and that survives a
// round trip through scenario_to_yaml(), or is refused with a SettingsError naming the file.
// Any other exception escaping parse_scenario() is a crash here, as it would end the program.

#include <string>

#include "fuzz_target.hpp"
#include "sim/scenario.hpp"
#include "sim/scenario_schema.hpp"
#include "yaml_schema/settings_error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace oasis::hw;
  sim::HallwayScenario scenario;
  try {
    scenario = sim::parse_scenario(oasis::fuzz::text_of(data, size), "fuzz.yaml");
  } catch (const yaml_schema::SettingsError& error) {
    FUZZ_REQUIRE(std::string(error.what()).find("fuzz.yaml") != std::string::npos);
    return 0;
  }
  FUZZ_REQUIRE(sim::detail::cross_check(scenario).empty());
  try {
    const sim::HallwayScenario back =
        sim::parse_scenario(sim::scenario_to_yaml(scenario), "written.yaml");
    FUZZ_REQUIRE(sim::differing_keys(scenario, back).empty());
  } catch (const yaml_schema::SettingsError& error) {
    oasis::fuzz::broken(error.what(), __FILE__, __LINE__);  // accepted, written, refused
  }
  return 0;
}
