#pragma once
// The subcommands of oasisc-mpi. Each registers its options and returns the exit status when
// run, the same on every rank: 0 success, 1 the input has errors or output failed.

#include <functional>

#include <CLI/CLI.hpp>

#include "distributed/communicator.hpp"

namespace oasis::mpi_cli {

using CommandRunner = std::function<int()>;

CommandRunner add_quotient_command(CLI::App& app, const distributed::Communicator& communicator);
CommandRunner add_compile_command(CLI::App& app, const distributed::Communicator& communicator);

}  // namespace oasis::mpi_cli
