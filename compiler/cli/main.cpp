// oasisc: the oasis abstraction compiler.

#include <cstdio>
#include <exception>
#include <map>
#include <new>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "command_line/empty_values.hpp"
#include "command_line/memory_option.hpp"
#include "support/error_report.hpp"
#include "support/gmp_allocation.hpp"
#include "support/interrupt_cleanup.hpp"
#include "support/standard_output.hpp"

namespace {

// oasisc's command line: parsed, then the command run. Errors of the command are reported
// here; main() catches what escapes the set-up.
int run(int argc, char** argv) {
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
  add(oasis::cli::add_query_command(app));
  add(oasis::cli::add_export_command(app));
  add(oasis::cli::add_quotient_command(app));
  add(oasis::cli::add_compile_command(app));
  add(oasis::cli::add_verify_command(app));
  add(oasis::cli::add_fit_command(app));

  std::string memory_budget = "auto";
  oasis::cli::add_memory_budget_option(app, memory_budget);
  oasis::cli::refuse_empty_values(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return oasis::finish_standard_output(oasis::cli::kProgram, app.exit(e));
  } catch (const CLI::CallForVersion& e) {
    return oasis::finish_standard_output(oasis::cli::kProgram, app.exit(e));
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return 2;  // bad usage, distinct from 1 (the input has errors)
  }
  const std::optional<std::uint64_t> budget =
      oasis::cli::apply_memory_budget_option(app, memory_budget, oasis::cli::kProgram);
  if (!budget) return oasis::finish_standard_output(oasis::cli::kProgram, 2);
  int status = 2;
  try {
    for (const CLI::App* command : app.get_subcommands())
      status = runners.at(command)();
  } catch (const std::bad_alloc&) {
    // Everything the command allocated is released by now, so the message can be built.
    oasis::cli::report_out_of_memory(oasis::cli::kProgram, *budget);
    status = 1;
  } catch (const std::exception& e) {
    oasis::report_error(oasis::cli::kProgram, e.what());
    status = 1;
  }
  return oasis::finish_standard_output(oasis::cli::kProgram, status);
}

}  // namespace

int main(int argc, char** argv) {
  oasis::make_gmp_throw_on_allocation_failure();
  oasis::interrupt::install_cleanup_handlers();  // a killed compile takes its staging with it
  try {
    return run(argc, argv);
  } catch (...) {
    // Only the set-up of the command line is left outside run()'s handlers: out of memory
    // before any command ran. No allocation here.
    std::fputs("oasisc: error: could not set up the command line\n", stderr);
    return 1;
  }
}
