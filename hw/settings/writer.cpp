// settings_to_yaml(): the schema writer (settings_visitors.hpp) prints every key of schema.hpp with
// its value and comment. Its output for default_settings() is hw/config/go1.yaml, byte for byte
// (a test holds the two together).

#include "settings/schema.hpp"
#include "settings/settings_visitors.hpp"

namespace oasis::hw::settings {

namespace detail {
namespace {

constexpr std::string_view kBanner =
    "# oasis-go1 settings (hw/settings/README.md), written by settings_to_yaml()\n"
    "# (`oasis-go1 config`). Every key is here with its meaning; a file may hold only\n"
    "# the keys that differ from the defaults, and an unknown key is an error. The defaults are\n"
    "# hw/config/go1.yaml: regenerate that file from the code, do not edit it by hand.\n";

}  // namespace
}  // namespace detail

std::string settings_to_yaml(const Go1Settings& settings) {
  detail::SettingsWriter writer{std::string(detail::kBanner)};
  detail::describe(writer, settings);
  return writer.text();
}

}  // namespace oasis::hw::settings
