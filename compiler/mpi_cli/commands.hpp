#pragma once
// The subcommands of oasisc-mpi. Each registers its options and returns the exit status when
// run, the same on every rank: 0 success, 1 the input has errors or output failed.

#include <functional>
#include <string_view>

#include <CLI/CLI.hpp>

#include "distributed/communicator.hpp"

namespace oasis::mpi_cli {

// The name oasisc-mpi's messages begin with when they belong to no file.
inline constexpr std::string_view kProgram = "oasisc-mpi";

using CommandRunner = std::function<int()>;

CommandRunner add_quotient_command(CLI::App& app, const distributed::Communicator& communicator);
CommandRunner add_compile_command(CLI::App& app, const distributed::Communicator& communicator);

}  // namespace oasis::mpi_cli
