// common/command_line/output_names.hpp: the CLI11 check of an option that names a file inside the
// output folder (--basename of oasisc compile and oasisc-mpi compile), on the one rule for output
// names (common/files/output_names.hpp): a plain name, never a path, so that the command
// writes nowhere else.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "files/output_names.hpp"

namespace oasis::cli {

inline CLI::Validator plain_file_name() {
  return CLI::Validator(
      [](std::string& name) -> std::string { return files::plain_file_name_problem(name); },
      "NAME");
}

}  // namespace oasis::cli
