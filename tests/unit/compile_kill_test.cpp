// `oasisc compile` killed at random points (SIGKILL: no clean-up runs) leaves its output
// directory holding either the whole old set of files or the whole new set, byte for byte,
// and nothing else; the next compile removes what the killed ones left beside it.

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <map>
#include <random>
#include <string>
#include <thread>

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include "../support/scratch_directory.hpp"

namespace oasis {
namespace {

namespace fs = std::filesystem;
using Files = std::map<std::string, std::string>;  // name -> bytes

Files snapshot(const fs::path& directory) {
  Files files;
  if (!fs::exists(directory)) return files;
  for (const auto& entry : fs::directory_iterator(directory)) {
    std::ifstream in(entry.path(), std::ios::binary);
    files[entry.path().filename().string()] = {std::istreambuf_iterator<char>(in),
                                               std::istreambuf_iterator<char>()};
  }
  return files;
}

// Starts `oasisc compile SPEC -o OUT ...` with stdout and stderr discarded.
pid_t start_compile(const std::string& spec, const fs::path& out) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int null = ::open("/dev/null", O_WRONLY);
    ::dup2(null, 1);
    ::dup2(null, 2);
    ::execl(OASISC_PATH, OASISC_PATH, "compile", spec.c_str(), "-o", out.c_str(), "--format",
            "bin,json,cpp", "--epsilon", "0.2", "--progress", "never", static_cast<char*>(nullptr));
    ::_exit(127);
  }
  return pid;
}

int wait_for(pid_t pid) {
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::size_t staging_siblings(const fs::path& parent) {
  std::size_t count = 0;
  for (const auto& entry : fs::directory_iterator(parent))
    if (entry.path().filename().string().find(".oasisc-staging.") != std::string::npos) ++count;
  return count;
}

TEST(CompileKill, TheOutputDirectoryIsAlwaysOneWholeSet) {
  const test::ScratchDirectory scratch("oasis_compile_kill");
  const std::string old_spec = std::string(OASIS_SOURCE_DIR) + "/specs/discrete_tracking.oasis";
  const std::string new_spec = std::string(OASIS_SOURCE_DIR) + "/specs/go1_treat.oasis";
  // The reference sets, and how long the slow compile takes here (ASan or not).
  ASSERT_EQ(wait_for(start_compile(old_spec, scratch.path() / "old")), 0);
  const auto begin = std::chrono::steady_clock::now();
  ASSERT_EQ(wait_for(start_compile(new_spec, scratch.path() / "new")), 0);
  const double full =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  const Files old_set = snapshot(scratch.path() / "old");
  const Files new_set = snapshot(scratch.path() / "new");
  ASSERT_FALSE(old_set.empty());
  ASSERT_NE(old_set, new_set);

  const fs::path out = scratch.path() / "out";
  const unsigned seed = 20261124;
  std::cout << "seed " << seed << ", full compile " << full << " s\n";
  std::mt19937 random(seed);
  int saw_old = 0;
  int saw_new = 0;
  for (int trial = 0; trial < 15; ++trial) {
    if (snapshot(out) != old_set) {
      ASSERT_EQ(wait_for(start_compile(old_spec, out)), 0);
    }
    const pid_t pid = start_compile(new_spec, out);
    // Half the kills anywhere, half near the end, where the files are written and swapped.
    const double low = trial % 2 == 0 ? 0.0 : 0.75 * full;
    const double delay = std::uniform_real_distribution<double>(low, 1.1 * full)(random);
    std::this_thread::sleep_for(std::chrono::duration<double>(delay));
    ::kill(pid, SIGKILL);
    wait_for(pid);
    const Files now = snapshot(out);
    const bool is_old = now == old_set;
    const bool is_new = now == new_set;
    ASSERT_TRUE(is_old || is_new) << "trial " << trial << " (killed after " << delay
                                  << " s): the folder holds " << now.size()
                                  << " files, neither whole set";
    (is_old ? saw_old : saw_new) += 1;
  }
  std::cout << "old set " << saw_old << " times, new set " << saw_new << " times\n";
  // A successful compile cleans up what the killed ones left beside the folder.
  ASSERT_EQ(wait_for(start_compile(new_spec, out)), 0);
  EXPECT_EQ(snapshot(out), new_set);
  EXPECT_EQ(staging_siblings(scratch.path()), 0U);
}

}  // namespace
}  // namespace oasis
