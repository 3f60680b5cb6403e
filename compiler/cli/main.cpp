// oasisc: the oasis abstraction compiler.

#include <iostream>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "cli/empty_values.hpp"
#include "support/gmp_allocation.hpp"
#include "support/interrupt_cleanup.hpp"
#include "support/limits.hpp"
#include "support/memory_budget.hpp"
#include "support/standard_output.hpp"

namespace {

constexpr const char* kMemoryBudgetFlag = "--memory-budget";

// --memory-budget on every command that runs (the leaves: `fit switching`, not `fit`), so that
// it reads `oasisc compile SPEC --memory-budget 4G` like every other option.
void add_memory_budget_option(CLI::App& command, std::string& budget) {
  const std::vector<CLI::App*> children = command.get_subcommands({});
  if (!children.empty()) {
    for (CLI::App* child : children)
      add_memory_budget_option(*child, budget);
    return;
  }
  std::string help =
      "Stop with an error, instead of being killed, when the command would allocate more than "
      "this: a size (512M, 4G), a percentage of the machine's memory (RAM, or the control "
      "group's limit when smaller), auto (" +
      std::to_string(oasis::limits::kDefaultMemoryBudgetPercent) + "%) or none";
  if (!oasis::memory_budget_enforceable())
    help += " (not enforced in this sanitizer build, whose shadow memory a limit would refuse)";
  command.add_option(kMemoryBudgetFlag, budget, help)->capture_default_str();
}

// The command that runs: the last parsed subcommand at each level.
const CLI::App* leaf_command(const CLI::App& app) {
  const CLI::App* command = &app;
  while (!command->get_subcommands().empty())
    command = command->get_subcommands().back();
  return command;
}

// Applies the budget the user gave (or the default). Returns the bytes in force (0: none), or
// nullopt after reporting a bad value.
std::optional<std::uint64_t> apply_budget(const CLI::App& app, const std::string& text) {
  const bool given = leaf_command(app)->count(kMemoryBudgetFlag) > 0;
  if (!oasis::memory_budget_enforceable()) {
    if (given)
      std::cerr << "oasisc: warning: " << kMemoryBudgetFlag
                << " is not enforced in this sanitizer build\n";
    return 0;
  }
  std::string error;
  const auto bytes = oasis::parse_memory_budget(text, error);
  const auto in_force = bytes ? oasis::apply_memory_budget(*bytes, error) : std::nullopt;
  if (!in_force) std::cerr << "oasisc: error: " << kMemoryBudgetFlag << ": " << error << '\n';
  return in_force;
}

}  // namespace

int main(int argc, char** argv) {
  oasis::make_gmp_throw_on_allocation_failure();
  oasis::interrupt::install_cleanup_handlers();  // a killed compile takes its staging with it
  CLI::App app{"oasisc " OASIS_VERSION
               ": compile MDP context specs into bisimulation abstractions for Online "
               "Attention Switching",
               "oasisc"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("oasisc ") + OASIS_VERSION);
  app.footer(
      "Run 'oasisc COMMAND --help' for a command's options. The spec language is\n"
      "described in docs/spec-language.md; every limit (file sizes, number sizes, states,\n"
      "cells, the memory budget) and its flag in docs/RELIABILITY.md, 'Limits'.");

  std::map<const CLI::App*, oasis::cli::CommandRunner> runners;
  auto add = [&](oasis::cli::CommandRunner runner) {
    runners.emplace(app.get_subcommands({}).back(), std::move(runner));
  };
  add(oasis::cli::add_check_command(app));
  add(oasis::cli::add_info_command(app));
  add(oasis::cli::add_export_command(app));
  add(oasis::cli::add_quotient_command(app));
  add(oasis::cli::add_compile_command(app));
  add(oasis::cli::add_verify_command(app));
  add(oasis::cli::add_fit_command(app));

  std::string memory_budget = "auto";
  add_memory_budget_option(app, memory_budget);
  oasis::cli::refuse_empty_values(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return oasis::finish_standard_output("oasisc", app.exit(e));
  } catch (const CLI::CallForVersion& e) {
    return oasis::finish_standard_output("oasisc", app.exit(e));
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return 2;  // bad usage, distinct from 1 (the input has errors)
  }
  const std::optional<std::uint64_t> budget = apply_budget(app, memory_budget);
  if (!budget) return oasis::finish_standard_output("oasisc", 2);
  int status = 2;
  try {
    for (const CLI::App* command : app.get_subcommands())
      status = runners.at(command)();
  } catch (const std::bad_alloc&) {
    // Everything the command allocated is released by now, so the message can be built.
    if (*budget == 0) {
      std::cerr << "oasisc: error: out of memory\n";
    } else {
      std::cerr << "oasisc: error: out of memory: the command needs more than its memory budget "
                   "of "
                << oasis::describe_bytes(*budget) << " (" << kMemoryBudgetFlag
                << "; the default is " << oasis::limits::kDefaultMemoryBudgetPercent
                << "% of the machine's memory)\n";
    }
    status = 1;
  } catch (const std::exception& e) {
    std::cerr << "oasisc: error: " << e.what() << '\n';
    status = 1;
  }
  return oasis::finish_standard_output("oasisc", status);
}
