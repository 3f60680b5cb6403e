#pragma once
// A fresh, empty directory for one test, named after the process and the running test, and
// removed with everything in it when the object goes away, also when an assertion ends the
// test early.

#include <filesystem>
#include <string>
#include <string_view>

#include <gtest/gtest.h>
#include <unistd.h>

namespace oasis::test {

class ScratchDirectory {
 public:
  explicit ScratchDirectory(std::string_view prefix)
      : path_(std::filesystem::temp_directory_path() /
              (std::string(prefix) + "_" + std::to_string(::getpid()) + "_" + test_name())) {
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ScratchDirectory(const ScratchDirectory&) = delete;
  ScratchDirectory& operator=(const ScratchDirectory&) = delete;
  ~ScratchDirectory() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }

  [[nodiscard]] const std::filesystem::path& path() const { return path_; }

 private:
  // One path component: a parameterised test's name holds a '/' ("Case/param"), which would
  // make the scratch directory a subdirectory of one that is never removed.
  static std::string test_name() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = info != nullptr ? info->name() : "outside_a_test";
    for (char& c : name)
      if (c == '/') c = '_';
    return name;
  }

  std::filesystem::path path_;
};

}  // namespace oasis::test
