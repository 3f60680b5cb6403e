#pragma once
// The subcommands of oasis-go1. Each add_* registers its options on `app` and returns the
// function that runs it once parsed; the function returns the exit status (0 done, 1 an
// error that was reported on standard error).
#include <functional>

#include <CLI/CLI.hpp>

namespace oasis::hw::app {

using CommandRunner = std::function<int()>;

CommandRunner add_run_command(CLI::App& app);
CommandRunner add_replay_command(CLI::App& app);
CommandRunner add_record_command(CLI::App& app);
CommandRunner add_score_command(CLI::App& app);
CommandRunner add_config_command(CLI::App& app);
CommandRunner add_sim_command(CLI::App& app);

}  // namespace oasis::hw::app
