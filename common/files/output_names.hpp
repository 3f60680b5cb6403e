// common/files/output_names.hpp: the one rule for the names of the files a program writes
// (oasisc, oasisc-mpi, and the catalog writers under them). Header-only, C++17.
//
// Two ways a command could write where it was not told to:
//   a name meant for a file inside the output folder (--basename, a file named after a
//   context or a model) that is a path instead: "../mine", "/etc/x", "." or "" leave the
//   folder or name it. A PRISM reward structure may be called "a/../../x";
//   several inputs whose outputs get the same name (a/x.aut and b/x.aut both to DIR/x.json):
//   the second replaces the first, and the first result is lost without a word.
// plain_file_name_problem() refuses the first; first_shared_output() finds the second, so that
// a command refuses it before any work, naming both inputs. common/command_line/output_names.hpp
// makes the first a CLI11 check.
#pragma once

#include <cstddef>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "text/printable_text.hpp"

namespace oasis::files {

// "" when `name` names a file inside a folder (no '/', not "." or "..", not empty, no NUL);
// otherwise why not, quoting it as every message quotes input.
inline std::string plain_file_name_problem(const std::string& name) {
  const bool plain = !name.empty() && name != "." && name != ".." &&
                     name.find('/') == std::string::npos && name.find('\0') == std::string::npos;
  if (plain) return "";
  return "\"" + text::printable_excerpt(name) +
         "\" is not a plain file name (no '/', not '.' or '..', not empty)";
}

// The first two indices whose outputs are the same file (compared as lexically normal paths,
// so "dir//x.json" and "dir/./x.json" are one), or nullopt when every output is its own.
inline std::optional<std::pair<std::size_t, std::size_t>> first_shared_output(
    const std::vector<std::string>& outputs) {
  std::map<std::filesystem::path, std::size_t> seen;
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    const auto [at, inserted] =
        seen.emplace(std::filesystem::path(outputs[i]).lexically_normal(), i);
    if (!inserted) return std::pair{at->second, i};
  }
  return std::nullopt;
}

}  // namespace oasis::files
