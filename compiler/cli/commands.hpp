#pragma once
// The subcommands of oasisc. Each registers its options on the CLI11 app and returns the
// exit status when run: 0 success, 1 the input has errors, 2 bad usage.

#include <functional>
#include <string_view>

#include <CLI/CLI.hpp>

#include "input/model_loader.hpp"

namespace oasis::cli {

// The name oasisc's messages begin with when they belong to no file.
inline constexpr std::string_view kProgram = "oasisc";

using input::load_model;
using input::LoadedModel;
using input::LoadOptions;

// Options every subcommand that reads models shares.
struct CommonOptions {
  LoadOptions load;
  std::size_t max_errors = limits::kDefaultMaxErrors;
  std::string progress = "auto";  // auto | always | never
};

void add_common_options(CLI::App& command, CommonOptions& options);
// Resolves "auto" progress against whether stderr is a terminal.
LoadOptions effective_load_options(const CommonOptions& options);

using CommandRunner = std::function<int()>;

CommandRunner add_check_command(CLI::App& app);
CommandRunner add_info_command(CLI::App& app);
CommandRunner add_export_command(CLI::App& app);
CommandRunner add_quotient_command(CLI::App& app);
CommandRunner add_compile_command(CLI::App& app);
CommandRunner add_verify_command(CLI::App& app);
CommandRunner add_fit_command(CLI::App& app);
CommandRunner add_query_command(CLI::App& app);

}  // namespace oasis::cli
