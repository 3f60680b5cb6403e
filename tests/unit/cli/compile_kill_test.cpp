// `oasisc compile` killed at random points (SIGKILL: no clean-up runs) leaves its output
// directory holding either the whole old set of files or the whole new set, byte for byte,
// and nothing else; the next compile removes what the killed ones left beside it. The same
// for one file written with -o (support/atomic_file.hpp): the old or the new file, whole.

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
#include <vector>

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include "../../support/file_snapshot.hpp"
#include "../../support/scratch_directory.hpp"

namespace oasis {
namespace {

namespace fs = std::filesystem;
using test::Files;
using test::snapshot;

// Starts `oasisc ARGUMENTS... --progress never` with stdout and stderr discarded.
pid_t start_oasisc(std::vector<std::string> arguments) {
  arguments.insert(arguments.begin(), OASISC_PATH);
  arguments.insert(arguments.end(), {"--progress", "never"});
  std::vector<char*> argv;
  for (std::string& argument : arguments)
    argv.push_back(argument.data());
  argv.push_back(nullptr);
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int null = ::open("/dev/null", O_WRONLY);
    ::dup2(null, 1);
    ::dup2(null, 2);
    ::execv(OASISC_PATH, argv.data());
    ::_exit(127);
  }
  return pid;
}

// `oasisc compile SPEC -o OUT` of three formats.
pid_t start_compile(const std::string& spec, const fs::path& out) {
  return start_oasisc(
      {"compile", spec, "-o", out.string(), "--format", "bin,json,cpp", "--epsilon", "0.2"});
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

// Every name in `directory` that is not `keep`: what a killed writer could leave behind.
std::vector<std::string> others(const fs::path& directory, const std::string& keep) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(directory))
    if (entry.path().filename() != keep) names.push_back(entry.path().filename().string());
  return names;
}

// The two reference sets the kill tests swap between (a small spec's and the Go1 spec's,
// compiled into `folder`/old and `folder`/new), and how long the slow compile takes here (ASan
// or not).
struct References {
  std::string old_spec = std::string(OASIS_SOURCE_DIR) + "/specs/discrete_tracking.oasis";
  std::string new_spec = std::string(OASIS_SOURCE_DIR) + "/specs/go1_treat.oasis";
  Files old_set;
  Files new_set;
  double full_seconds = 0;
};

References compile_references(const fs::path& folder) {
  References references;
  EXPECT_EQ(wait_for(start_compile(references.old_spec, folder / "old")), 0);
  const auto begin = std::chrono::steady_clock::now();
  EXPECT_EQ(wait_for(start_compile(references.new_spec, folder / "new")), 0);
  references.full_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  references.old_set = snapshot(folder / "old");
  references.new_set = snapshot(folder / "new");
  return references;
}

TEST(CompileKill, TheOutputDirectoryIsAlwaysOneWholeSet) {
  const test::ScratchDirectory scratch("oasis_compile_kill");
  const References references = compile_references(scratch.path());
  ASSERT_FALSE(references.old_set.empty());
  ASSERT_NE(references.old_set, references.new_set);
  const std::string& old_spec = references.old_spec;
  const std::string& new_spec = references.new_spec;
  const Files& old_set = references.old_set;
  const Files& new_set = references.new_set;
  const double full = references.full_seconds;

  const fs::path out = scratch.path() / "out";
  const unsigned seed = 20261124;
  std::cout << "seed " << seed << ", full compile " << full << " s\n";
  std::mt19937 random(seed);
  int saw_old = 0;
  int saw_new = 0;
  for (int trial = 0; trial < 15; ++trial) {
    if (snapshot(out) != old_set) {
      ASSERT_EQ(wait_for(start_compile(old_spec, out)), 0);
      // A whole compile removes what earlier killed ones left beside the folder.
      EXPECT_EQ(staging_siblings(scratch.path()), 0U) << "trial " << trial;
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
    // Beside the folder, only the reference sets and killed compiles' staging folders.
    for (const std::string& name : others(scratch.path(), "out")) {
      EXPECT_TRUE(name == "old" || name == "new" || name.rfind(".out.oasisc-staging.", 0) == 0)
          << "trial " << trial << ": " << name;
    }
    (is_old ? saw_old : saw_new) += 1;
  }
  std::cout << "old set " << saw_old << " times, new set " << saw_new << " times\n";
  // A successful compile cleans up what the killed ones left beside the folder.
  ASSERT_EQ(wait_for(start_compile(new_spec, out)), 0);
  EXPECT_EQ(snapshot(out), new_set);
  EXPECT_EQ(staging_siblings(scratch.path()), 0U);
}

// SIGTERM and SIGINT (support/interrupt_cleanup.hpp): the folder is still one whole set, the
// program dies of the signal (or had finished), and, unlike SIGKILL, it leaves nothing beside
// the folder: its staging directory goes with it.
TEST(CompileKill, SigtermAndSigintLeaveNothingBehind) {
  const test::ScratchDirectory scratch("oasis_compile_term");
  const References references = compile_references(scratch.path());
  ASSERT_FALSE(references.old_set.empty());
  ASSERT_NE(references.old_set, references.new_set);
  const std::string& old_spec = references.old_spec;
  const std::string& new_spec = references.new_spec;
  const Files& old_set = references.old_set;
  const Files& new_set = references.new_set;
  const double full = references.full_seconds;

  const fs::path out = scratch.path() / "out";
  std::mt19937 random(20261126);
  int signalled = 0;
  for (int trial = 0; trial < 10; ++trial) {
    const int signal_number = trial % 2 == 0 ? SIGTERM : SIGINT;
    if (snapshot(out) != old_set) {
      ASSERT_EQ(wait_for(start_compile(old_spec, out)), 0);
    }
    const pid_t pid = start_compile(new_spec, out);
    const double delay = std::uniform_real_distribution<double>(0.1 * full, 1.1 * full)(random);
    std::this_thread::sleep_for(std::chrono::duration<double>(delay));
    ::kill(pid, signal_number);
    int status = 0;
    ::waitpid(pid, &status, 0);
    const bool died_of_it = WIFSIGNALED(status) && WTERMSIG(status) == signal_number;
    const bool finished = WIFEXITED(status) && WEXITSTATUS(status) == 0;
    EXPECT_TRUE(died_of_it || finished) << "trial " << trial << ": status " << status;
    signalled += died_of_it ? 1 : 0;
    const Files now = snapshot(out);
    ASSERT_TRUE(now == old_set || now == new_set) << "trial " << trial;
    EXPECT_EQ(staging_siblings(scratch.path()), 0U)
        << "trial " << trial << " after signal " << signal_number;
  }
  std::cout << signalled << " of 10 compiles died of the signal, the rest had finished\n";
  EXPECT_GT(signalled, 0);
}

// A model large enough that writing its copy takes a while: a chain of `states` states with
// two actions, one of them a coin flip.
std::string chain_aut(std::uint32_t states) {
  std::string text = "des (0," + std::to_string(2 * states) + "," + std::to_string(states) + ")\n";
  for (std::uint32_t s = 0; s < states; ++s) {
    const std::string next = std::to_string((s + 1) % states);
    text += "(" + std::to_string(s) + ",\"go\"," + next + ")\n";
    text += "(" + std::to_string(s) + ",\"flip|reward(1/3)\"," + next + " 1/3 " +
            std::to_string(s) + ")\n";
  }
  return text;
}

// `oasisc export MODEL --format aut -o OUT`: one file.
pid_t start_export(const fs::path& model, const fs::path& out) {
  return start_oasisc({"export", model.string(), "--format", "aut", "-o", out.string()});
}

// An empty output folder `root`/out, and two models beside it: a small one and one whose copy
// takes a while to write, so that kills land in every step.
struct FolderAndModels {
  fs::path folder;
  fs::path small;
  fs::path big;
};

FolderAndModels output_folder_and_models(const fs::path& root) {
  FolderAndModels made{root / "out", root / "small.aut", root / "big.aut"};
  fs::create_directories(made.folder);
  std::ofstream(made.small, std::ios::binary) << chain_aut(3);
  std::ofstream(made.big, std::ios::binary) << chain_aut(300000);
  return made;
}

std::string bytes_of(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// One file written with -o, killed at random points: the file is the old one or the new one,
// whole. The temporary file is anonymous until its last step (O_TMPFILE), so a kill leaves
// nothing, except in the instant between naming it and renaming it over the old file: then a
// complete copy may stay, which the next writer of the same file removes.
TEST(CompileKill, OneOutputFileIsOldOrNewAndNothingStays) {
  const test::ScratchDirectory scratch("oasis_export_kill");
  const auto [folder, small, big] = output_folder_and_models(scratch.path());
  const fs::path out = folder / "model.aut";

  ASSERT_EQ(wait_for(start_export(big, out)), 0);
  const std::string new_bytes = bytes_of(out);
  const auto begin = std::chrono::steady_clock::now();
  ASSERT_EQ(wait_for(start_export(small, out)), 0);
  ASSERT_EQ(wait_for(start_export(big, out)), 0);
  const double full =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  ASSERT_EQ(wait_for(start_export(small, out)), 0);
  const std::string old_bytes = bytes_of(out);
  ASSERT_NE(old_bytes, new_bytes);

  const unsigned seed = 20261125;
  std::cout << "seed " << seed << ", full export " << full << " s\n";
  std::mt19937 random(seed);
  int saw_old = 0;
  int saw_new = 0;
  for (int trial = 0; trial < 20; ++trial) {
    if (bytes_of(out) != old_bytes) {
      ASSERT_EQ(wait_for(start_export(small, out)), 0);
      EXPECT_EQ(others(folder, "model.aut"), std::vector<std::string>{}) << "trial " << trial;
    }
    const pid_t pid = start_export(big, out);
    const double delay = std::uniform_real_distribution<double>(0.0, 1.1 * full)(random);
    std::this_thread::sleep_for(std::chrono::duration<double>(delay));
    ::kill(pid, SIGKILL);
    wait_for(pid);
    const std::string now = bytes_of(out);
    ASSERT_TRUE(now == old_bytes || now == new_bytes)
        << "trial " << trial << " (killed after " << delay << " s): the file has " << now.size()
        << " bytes, neither whole file";
    (now == old_bytes ? saw_old : saw_new) += 1;
    for (const std::string& name : others(folder, "model.aut")) {
      EXPECT_EQ(name.rfind(".model.aut.tmp.", 0), 0U) << "trial " << trial << ": " << name;
      EXPECT_EQ(bytes_of(folder / name), new_bytes) << "trial " << trial << ": " << name;
    }
  }
  std::cout << "old file " << saw_old << " times, new file " << saw_new << " times\n";
  ASSERT_EQ(wait_for(start_export(small, out)), 0);
  EXPECT_EQ(bytes_of(out), old_bytes);
  EXPECT_EQ(others(folder, "model.aut"), std::vector<std::string>{});
}

// `oasisc export MODEL --format prism -o BASE`: a set of files (.tra, .lab, .srew).
pid_t start_prism_export(const fs::path& model, const fs::path& base) {
  return start_oasisc({"export", model.string(), "--format", "prism", "-o", base.string()});
}

// The files of the set written to BASE (model.tra, model.lab, ...), without hidden ones.
Files visible_set(const fs::path& folder) {
  Files files = snapshot(folder);
  std::erase_if(files, [](const auto& entry) { return entry.first.rfind("model.", 0) != 0; });
  return files;
}

// A set of files killed at random points: after the next oasisc run that writes in the folder
// (here, an export to another name), the set is wholly the old one or wholly the new one, and
// nothing hidden is left: a kill in the middle of the renames is finished from the journal
// (support/file_set_journal.hpp; the deterministic kill after each rename is in
// atomic_file_set_test).
TEST(CompileKill, AFileSetIsWholeAfterTheNextRun) {
  const test::ScratchDirectory scratch("oasis_set_kill");
  const auto [folder, small, big] = output_folder_and_models(scratch.path());
  const fs::path base = folder / "model";
  const fs::path other = folder / "other";

  ASSERT_EQ(wait_for(start_prism_export(small, base)), 0);
  const auto begin = std::chrono::steady_clock::now();
  ASSERT_EQ(wait_for(start_prism_export(big, base)), 0);
  const double full =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  const Files new_set = visible_set(folder);
  ASSERT_EQ(wait_for(start_prism_export(small, base)), 0);
  const Files old_set = visible_set(folder);
  ASSERT_GE(old_set.size(), 2U);
  ASSERT_NE(old_set, new_set);

  const unsigned seed = 20261128;
  std::mt19937 random(seed);
  int saw_old = 0;
  int saw_new = 0;
  for (int trial = 0; trial < 20; ++trial) {
    if (visible_set(folder) != old_set) {
      ASSERT_EQ(wait_for(start_prism_export(small, base)), 0);
    }
    const pid_t pid = start_prism_export(big, base);
    const double delay = std::uniform_real_distribution<double>(0.0, 1.1 * full)(random);
    std::this_thread::sleep_for(std::chrono::duration<double>(delay));
    ::kill(pid, SIGKILL);
    wait_for(pid);
    ASSERT_EQ(wait_for(start_prism_export(small, other)), 0);  // the next run in the folder
    const Files now = visible_set(folder);
    ASSERT_TRUE(now == old_set || now == new_set)
        << "trial " << trial << " (killed after " << delay << " s): a mix of two sets";
    (now == old_set ? saw_old : saw_new) += 1;
    // Killed before its renames began, a writer may leave complete temporaries of its own
    // files (removed by the next write of that output); never a journal.
    for (const auto& entry : fs::directory_iterator(folder)) {
      const std::string name = entry.path().filename().string();
      EXPECT_TRUE(name.rfind("model.", 0) == 0 || name.rfind("other.", 0) == 0 ||
                  (name.rfind(".model.", 0) == 0 && name.find(".tmp.") != std::string::npos))
          << "trial " << trial << ": " << name << " left behind";
    }
  }
  std::cout << "seed " << seed << ": old set " << saw_old << " times, new set " << saw_new
            << " times\n";
  ASSERT_EQ(wait_for(start_prism_export(small, base)), 0);
  for (const auto& entry : fs::directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    EXPECT_TRUE(name.rfind("model.", 0) == 0 || name.rfind("other.", 0) == 0) << name;
  }
}

}  // namespace
}  // namespace oasis
