// parse_settings() and load_settings(): the schema reader (schema_reader.hpp) walks
// schema.hpp over the file, then the checks across keys run (checks.hpp).

#include "settings/checks.hpp"
#include "settings/schema.hpp"
#include "settings/schema_reader.hpp"

namespace oasis::hw::settings {

Go1Settings parse_settings(std::string_view yaml_text, std::string_view file_name) {
  Go1Settings settings = default_settings();
  detail::parse_with_schema(
      yaml_text, file_name, settings,
      [](auto& visitor, auto& values) { detail::describe(visitor, values); },
      [](const Go1Settings& values) { return detail::cross_check(values); },
      "robot:, limits:, actions:, camera:, perception:, filter:, loop:, source:");
  return settings;
}

Go1Settings load_settings(const std::filesystem::path& file) {
  return parse_settings(detail::read_yaml_file(file), file.string());
}

}  // namespace oasis::hw::settings
