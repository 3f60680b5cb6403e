#pragma once
// --memory-budget, the same on every command of oasisc, oasis-sim and oasis-go1: declared on each
// command that runs (the leaves, so that it reads `oasisc compile SPEC --memory-budget 4G` like
// any other option), applied once the command line is parsed, and reported the same way when
// the budget runs out (memory_budget.hpp says how it is enforced).

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include <CLI/CLI.hpp>

namespace oasis::cli {

inline constexpr const char* kMemoryBudgetFlag = "--memory-budget";

// Adds the option to every leaf command under `app` (or to `app` when it has none), storing
// the text in `budget`, whose value on entry ("auto") is the default.
void add_memory_budget_option(CLI::App& app, std::string& budget);

// Applies the budget in `text` after parsing. Returns the bytes in force (0: none), or nullopt
// after printing "PROGRAM: error: --memory-budget: ..." (a usage error: status 2).
std::optional<std::uint64_t> apply_memory_budget_option(const CLI::App& app,
                                                        const std::string& text,
                                                        std::string_view program);

// The budget the command runs under, as apply_memory_budget_option() settled it: the bytes in
// force, or, in a sanitizer build that enforces no limit, the bytes asked for, so that what a
// command refuses by its own estimate (oasisc compile's interval MDP) still follows the option.
// 0: none (also before the option is applied).
std::uint64_t command_memory_budget();

// The message for a std::bad_alloc that reached main: "PROGRAM: error: out of memory: ...".
void report_out_of_memory(std::string_view program, std::uint64_t budget);

}  // namespace oasis::cli
