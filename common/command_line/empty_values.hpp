// common/command_line/empty_values.hpp: an empty value is an error on every option of every
// program.
//
// Why: an option's value is kept in a string (or a number) whose empty state means "not
// given", so `--catalog ''`, `-o ''` or `--json ''` silently meant the default, where the
// settings file refuses the same empty value. refuse_empty_values() walks a finished CLI11 app,
// its subcommands and their positionals, and gives every option that takes a value one more
// check, so no program can forget one.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace oasis::cli {

inline CLI::Validator non_empty() {
  return CLI::Validator(
      [](std::string& value) -> std::string {
        return value.empty() ? "an empty value; give one, or leave the option out for its default"
                             : "";
      },
      "");
}

// Call once every option is declared, before parsing.
inline void refuse_empty_values(CLI::App& app) {
  for (CLI::Option* option : app.get_options())
    if (option->get_type_size_max() > 0) option->check(non_empty());
  for (CLI::App* command : app.get_subcommands({}))
    refuse_empty_values(*command);
}

}  // namespace oasis::cli
