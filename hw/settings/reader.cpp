// parse_settings() and load_settings(): the schema reader (yaml_schema/schema_reader.hpp, with
// the settings' own entries: settings_visitors.hpp) walks schema.hpp over the file, then the
// checks across keys run (checks.hpp).

#include "settings/checks.hpp"
#include "settings/schema.hpp"
#include "settings/settings_visitors.hpp"
#include "yaml_schema/schema_reader.hpp"

namespace oasis::hw::settings {
namespace {

// The controller's options moved from the settings into controller profiles (issue 22).
constexpr const char* kMovedToProfile =
    "the filter's options and the tag evidence live in controller profiles now "
    "(hw/config/controllers/); pick one with loop.controller or --controller, or write your own "
    "profile file and give its path";

}  // namespace

Go1Settings parse_settings(std::string_view yaml_text, std::string_view file_name) {
  Go1Settings settings = default_settings();
  yaml_schema::parse_with_schema<detail::SettingsVisitors>(
      yaml_text, file_name, settings,
      [](auto& visitor, auto& values) { detail::describe(visitor, values); },
      [](const Go1Settings& values) { return detail::cross_check(values); },
      "robot:, limits:, actions:, camera:, perception:, loop:, source:",
      {{"filter", kMovedToProfile},
       {"loop.treat_sighting", kMovedToProfile},
       {"loop.tag_unseen_likelihood", kMovedToProfile},
       {"loop.unknown_reward_when_tag_cut", kMovedToProfile}});
  return settings;
}

Go1Settings load_settings(const std::filesystem::path& file) {
  return parse_settings(yaml_schema::read_yaml_file(file), file.string());
}

}  // namespace oasis::hw::settings
