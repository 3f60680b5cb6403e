// The YAML settings of oasis-go1 (hw/settings): any text either gives settings that pass
// check_settings() and survive a round trip through settings_to_yaml(), or is refused with a
// SettingsError naming at least one problem. Any other exception (yaml-cpp's own, say)
// escaping parse_settings() is a crash here, as it would end oasis-go1.

#include "fuzz_target.hpp"
#include "settings/settings.hpp"
#include "settings/settings_error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace oasis::hw::settings;
  const std::string text = oasis::fuzz::text_of(data, size);
  Go1Settings settings;
  try {
    settings = parse_settings(text, "fuzz.yaml");
  } catch (const SettingsError& error) {
    FUZZ_REQUIRE(std::string(error.what()).find("fuzz.yaml") != std::string::npos);
    return 0;
  }
  FUZZ_REQUIRE(check_settings(settings).empty());
  try {
    FUZZ_REQUIRE(parse_settings(settings_to_yaml(settings), "written.yaml") == settings);
  } catch (const SettingsError& error) {
    oasis::fuzz::broken(error.what(), __FILE__, __LINE__);  // accepted, written, refused
  }
  return 0;
}
