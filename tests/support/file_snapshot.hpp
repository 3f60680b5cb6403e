#pragma once
// The regular files of one directory with their bytes, for tests that check what a command
// changed or left behind (an empty map when the directory does not exist).

#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>

namespace oasis::test {

using Files = std::map<std::string, std::string>;  // file name -> bytes

inline Files snapshot(const std::filesystem::path& directory) {
  Files files;
  if (!std::filesystem::exists(directory)) return files;
  for (const auto& entry : std::filesystem::directory_iterator(directory)) {
    if (!entry.is_regular_file()) continue;
    std::ifstream in(entry.path(), std::ios::binary);
    files[entry.path().filename().string()] = {std::istreambuf_iterator<char>(in),
                                               std::istreambuf_iterator<char>()};
  }
  return files;
}

}  // namespace oasis::test
