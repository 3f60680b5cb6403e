// `oasis-go1 config`: check a settings file and print the settings in effect; with
// --controller, check a controller profile and print it.

#include <iostream>
#include <memory>
#include <string>

#include "app/commands.hpp"
#include "loop/session.hpp"
#include "settings/controller_profile.hpp"
#include "settings/settings.hpp"

namespace oasis::hw::app {

CommandRunner add_config_command(CLI::App& app) {
  auto file = std::make_shared<std::string>();
  auto controller = std::make_shared<std::string>();
  CLI::App* command = app.add_subcommand(
      "config", "check a settings file (or a controller profile) and print it in full, as YAML");
  command->add_option("file", *file, "the settings file; default: the built-in defaults")
      ->check(CLI::ExistingFile);
  command->add_option("--controller", *controller,
                      "print this controller profile instead: " +
                          settings::shipped_profile_names() + ", or a .yaml profile to check");
  command->footer(
      "A file may hold only the keys that differ from the defaults; unknown keys are errors. "
      "The output is a complete file: 'oasis-go1 config > my.yaml' starts a settings file, "
      "'oasis-go1 config --controller ours > mine.yaml' a profile (then run --controller "
      "mine.yaml).");
  return [file, controller] {
    if (!controller->empty()) {
      std::cout << settings::profile_to_yaml(
          settings::find_controller_profile(*controller, "--controller"));
      return 0;
    }
    std::cout << settings::settings_to_yaml(loop::settings_or_defaults(*file));
    return 0;
  };
}

}  // namespace oasis::hw::app
