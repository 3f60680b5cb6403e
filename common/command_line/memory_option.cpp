#include "command_line/memory_option.hpp"

#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "command_line/memory_budget.hpp"
#include "text/byte_size.hpp"

namespace oasis::cli {
namespace {

// The command that runs: the last parsed subcommand at each level.
const CLI::App* leaf_command(const CLI::App& app) {
  const CLI::App* command = &app;
  while (!command->get_subcommands().empty())
    command = command->get_subcommands().back();
  return command;
}

// What the command ran out of: the budget, the address-space limit, or neither.
std::string out_of_memory_message(std::uint64_t budget) {
  // The address space holds the data the budget counts and more (mapped inputs, stacks, code):
  // a shell's `ulimit -v` at or below the budget is the limit that bit.
  const std::optional<std::uint64_t> address_space = address_space_limit();
  if (address_space && (budget == 0 || *address_space <= budget))
    return "out of memory: the command needs more than the address-space limit of " +
           text::describe_bytes(*address_space) +
           " set for it (ulimit -v, RLIMIT_AS; --memory-budget cannot raise it)";
  if (budget == 0) return "out of memory";
  std::string message = "out of memory: the command needs more than its memory budget of " +
                        text::describe_bytes(budget) + " (" + std::string(kMemoryBudgetFlag) +
                        "; the default is " + std::to_string(kDefaultMemoryBudgetPercent) +
                        "% of the machine's memory)";
  if (address_space)
    message +=
        " or the address-space limit of " + text::describe_bytes(*address_space) + " (ulimit -v)";
  return message;
}

}  // namespace

void add_memory_budget_option(CLI::App& app, std::string& budget) {
  const std::vector<CLI::App*> children = app.get_subcommands({});
  if (!children.empty()) {
    for (CLI::App* child : children)
      add_memory_budget_option(*child, budget);
    return;
  }
  std::string help =
      "Stop with an error, instead of being killed, when the command would allocate more than "
      "this: a size (512M, 4G), a percentage of the machine's memory (RAM, or the control "
      "group's limit when smaller), auto (" +
      std::to_string(kDefaultMemoryBudgetPercent) + "%) or none";
  if (!memory_budget_enforceable())
    help += " (not enforced in this sanitizer build, whose shadow memory a limit would refuse)";
  app.add_option(kMemoryBudgetFlag, budget, help)->capture_default_str();
}

namespace {
std::uint64_t settled_budget = 0;  // command_memory_budget(): set once, before the command runs
}  // namespace

std::uint64_t command_memory_budget() {
  return settled_budget;
}

std::optional<std::uint64_t> apply_memory_budget_option(const CLI::App& app,
                                                        const std::string& text,
                                                        std::string_view program) {
  const CLI::App* command = leaf_command(app);
  const bool given = command->get_option_no_throw(kMemoryBudgetFlag) != nullptr &&
                     command->count(kMemoryBudgetFlag) > 0;
  std::string error;
  const auto bytes = parse_memory_budget(text, error);  // a bad value is refused in every build
  if (bytes && !memory_budget_enforceable()) {
    if (given)
      std::cerr << program << ": warning: " << kMemoryBudgetFlag
                << " is not enforced in this sanitizer build\n";
    settled_budget = *bytes;
    return 0;
  }
  const auto in_force = bytes ? apply_memory_budget(*bytes, error) : std::nullopt;
  if (!in_force) std::cerr << program << ": error: " << kMemoryBudgetFlag << ": " << error << '\n';
  if (in_force) settled_budget = *in_force;
  return in_force;
}

void report_out_of_memory(std::string_view program, std::uint64_t budget) {
  // One write of the whole line: under mpirun every rank may report, and the job is killed as
  // soon as one rank aborts, so a line written in pieces came out cut or interleaved.
  std::string line(program);
  line += ": error: " + out_of_memory_message(budget) + "\n";
  std::cerr << line << std::flush;
}

}  // namespace oasis::cli
