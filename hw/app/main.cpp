// oasis-go1: Online Attention Switching on a Unitree Go1 - the 5 Hz loop camera -> perception
// -> filter -> policy -> robot, its logs and their Table II score.

#include <cstdio>
#include <iostream>
#include <map>
#include <new>
#include <optional>

#include <CLI/CLI.hpp>

#include "app/commands.hpp"
#include "app/print_error.hpp"
#include "command_line/empty_values.hpp"
#include "command_line/memory_option.hpp"
#include "perception/out_of_memory.hpp"
#include "settings/settings_error.hpp"

namespace {

// The program: its command line parsed, then the command run, every error of a command
// reported. main() catches what escapes the set-up.
int run(int argc, char** argv) {
  CLI::App app{
      "oasis-go1: follow whichever of two people holds the treat, with Online "
      "Attention Switching on a Unitree Go1",
      "oasis-go1"};
  app.require_subcommand(1);
  app.footer(
      "Start with a dry run on the synthetic world, which needs neither robot nor camera:\n"
      "  oasis-go1 run --dry-run --source synthetic --steps 150 --log run.jsonl\n"
      "  oasis-go1 score run.jsonl\n"
      "Table II in the simulated hallway, per controller: oasis-go1 sim --trials 12\n"
      "Before the real robot, read hw/README.md (\"On the robot\"). Run 'oasis-go1 COMMAND "
      "--help' for a command's options.");

  std::map<const CLI::App*, oasis::hw::app::CommandRunner> runners;
  auto add = [&](oasis::hw::app::CommandRunner runner) {
    runners.emplace(app.get_subcommands({}).back(), std::move(runner));
  };
  add(oasis::hw::app::add_run_command(app));
  add(oasis::hw::app::add_replay_command(app));
  add(oasis::hw::app::add_record_command(app));
  add(oasis::hw::app::add_score_command(app));
  add(oasis::hw::app::add_config_command(app));
  add(oasis::hw::app::add_sim_command(app));
  std::string memory_budget = "auto";
  oasis::cli::add_memory_budget_option(app, memory_budget);
  oasis::cli::refuse_empty_values(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int status = app.exit(e);
    return status == 0 ? 0 : 2;  // bad usage, distinct from 1 (an error in the input)
  }
  const std::optional<std::uint64_t> budget =
      oasis::cli::apply_memory_budget_option(app, memory_budget, oasis::hw::app::kProgram);
  if (!budget) return 2;
  try {
    for (const CLI::App* command : app.get_subcommands())
      return runners.at(command)();
  } catch (const std::exception& e) {
    // The robot was stopped on the way out (the loop's watchdog and the link's destructor).
    // OpenCV says it ran out of memory in its own words (perception/out_of_memory.hpp).
    if (oasis::hw::is_out_of_memory(e))
      oasis::cli::report_out_of_memory(oasis::hw::app::kProgram, *budget);
    else
      oasis::hw::app::print_error(e.what());
  }
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (...) {
    // Only the set-up of the command line is left outside run()'s handlers: out of memory
    // before any command ran. No allocation here.
    std::fputs("oasis-go1: error: could not set up the command line\n", stderr);
    return 1;
  }
}
