#pragma once
// A test fixture with its own scratch directory: files written into it, and the list of what is
// there, for end-to-end tests that check what a command left behind.

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

#include "run_oasisc.hpp"
#include "scratch_directory.hpp"

namespace oasis::test {

class ScratchFilesTest : public ::testing::Test {
 protected:
  explicit ScratchFilesTest(std::string_view prefix) : scratch_(prefix) {}

  std::filesystem::path write(const std::string& name, const std::string& text) const {
    const std::filesystem::path path = scratch_.path() / name;
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }

  // The names in the scratch directory, sorted.
  [[nodiscard]] std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(scratch_.path()))
      names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }

  ScratchDirectory scratch_;
};

inline bool output_has(const CommandResult& result, std::string_view text) {
  return result.output.find(text) != std::string::npos;
}

}  // namespace oasis::test
