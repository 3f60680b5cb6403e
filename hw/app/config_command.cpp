// `oasis-go1 config`: check a settings file and print the settings in effect.

#include <iostream>
#include <memory>
#include <string>

#include "app/commands.hpp"
#include "app/session.hpp"
#include "settings/settings.hpp"

namespace oasis::hw::app {

CommandRunner add_config_command(CLI::App& app) {
  auto file = std::make_shared<std::string>();
  CLI::App* command = app.add_subcommand(
      "config", "check a settings file and print every setting in effect, as YAML");
  command->add_option("file", *file, "the settings file; default: the built-in defaults")
      ->check(CLI::ExistingFile);
  command->footer(
      "A file may hold only the keys that differ from the defaults; unknown keys are errors. "
      "The output is a complete settings file: 'oasis-go1 config > my.yaml' starts one.");
  return [file] {
    std::cout << settings::settings_to_yaml(settings_or_defaults(*file));
    return 0;
  };
}

}  // namespace oasis::hw::app
