// An output directory that changes as one unit: created, replaced whole, refused when it
// holds files of someone else, and cleaned of the staging directories of killed writers.

#include "support/staged_directory.hpp"

#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/file.h>
#include <unistd.h>

#include "../../support/scratch_directory.hpp"

namespace oasis {
namespace {

namespace fs = std::filesystem;

void write(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

std::string read(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::set<std::string> listing(const fs::path& directory) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(directory))
    names.insert(entry.path().filename().string());
  return names;
}

class StagedDirectoryTest : public ::testing::Test {
 protected:
  // Commits a set of files {name: text} into `target`.
  bool commit_set(const fs::path& target, const std::set<std::string>& names, std::string& error) {
    StagedDirectory directory;
    if (!directory.open(target.string(), error)) return false;
    for (const std::string& name : names)
      write(fs::path(directory.staging_path()) / name, "content of " + name);
    return directory.commit("marker\n", error);
  }

  test::ScratchDirectory scratch_{"oasis_staged"};
};

TEST_F(StagedDirectoryTest, CreatesANewDirectoryWithTheSetAndTheMarker) {
  const fs::path target = scratch_.path() / "out";
  std::string error;
  ASSERT_TRUE(commit_set(target, {"a.bin", "a.json"}, error)) << error;
  EXPECT_EQ(listing(target), (std::set<std::string>{".oasisc-output", "a.bin", "a.json"}));
  EXPECT_EQ(read(target / "a.bin"), "content of a.bin");
  EXPECT_EQ(listing(scratch_.path()), (std::set<std::string>{"out"}));  // no staging left
}

TEST_F(StagedDirectoryTest, ReplacesAnOwnedDirectoryWhole) {
  const fs::path target = scratch_.path() / "out";
  std::string error;
  ASSERT_TRUE(commit_set(target, {"old.bin", "old.json"}, error)) << error;
  ASSERT_TRUE(commit_set(target, {"new.bin"}, error)) << error;
  EXPECT_EQ(listing(target), (std::set<std::string>{".oasisc-output", "new.bin"}));
  EXPECT_EQ(listing(scratch_.path()), (std::set<std::string>{"out"}));
}

TEST_F(StagedDirectoryTest, AcceptsAnEmptyDirectoryAndKeepsItsPermissionsSane) {
  const fs::path target = scratch_.path() / "empty";
  fs::create_directory(target);
  std::string error;
  ASSERT_TRUE(commit_set(target, {"a.bin"}, error)) << error;
  EXPECT_TRUE(fs::exists(target / "a.bin"));
  const auto permissions = fs::status(target).permissions();
  EXPECT_NE(permissions & fs::perms::group_read, fs::perms::none) << "not a private 0700 dir";
}

TEST_F(StagedDirectoryTest, RefusesADirectoryWithSomeoneElsesFilesAndTouchesNothing) {
  const fs::path target = scratch_.path() / "mine";
  fs::create_directory(target);
  write(target / "notes.txt", "do not delete");
  StagedDirectory directory;
  std::string error;
  EXPECT_FALSE(directory.open(target.string(), error));
  EXPECT_NE(error.find("holds files that oasisc did not write"), std::string::npos) << error;
  EXPECT_EQ(read(target / "notes.txt"), "do not delete");
  EXPECT_EQ(listing(scratch_.path()), (std::set<std::string>{"mine"}));
}

TEST_F(StagedDirectoryTest, RefusesAFile) {
  write(scratch_.path() / "file", "x");
  StagedDirectory directory;
  std::string error;
  EXPECT_FALSE(directory.open((scratch_.path() / "file").string(), error));
  EXPECT_NE(error.find("not a directory"), std::string::npos) << error;
}

TEST_F(StagedDirectoryTest, DiscardLeavesTheTargetAsItWas) {
  const fs::path target = scratch_.path() / "out";
  std::string error;
  ASSERT_TRUE(commit_set(target, {"old.bin"}, error)) << error;
  {
    StagedDirectory directory;
    ASSERT_TRUE(directory.open(target.string(), error)) << error;
    write(fs::path(directory.staging_path()) / "new.bin", "new");
  }  // destroyed uncommitted
  EXPECT_EQ(listing(target), (std::set<std::string>{".oasisc-output", "old.bin"}));
  EXPECT_EQ(listing(scratch_.path()), (std::set<std::string>{"out"}));
}

TEST_F(StagedDirectoryTest, StaleStagingOfAKilledWriterIsRemovedButALiveOneIsNot) {
  const fs::path target = scratch_.path() / "out";
  const fs::path stale = scratch_.path() / ".out.oasisc-staging.dead01";
  fs::create_directory(stale);
  write(stale / "huge.bin", std::string(1000, 'x'));
  // A live writer: its staging directory is locked (flock is per open file description, so
  // a second open in this process conflicts like another process would).
  StagedDirectory live;
  std::string error;
  ASSERT_TRUE(live.open(target.string(), error)) << error;
  EXPECT_FALSE(fs::exists(stale)) << "the dead writer's staging was not removed";
  ASSERT_TRUE(commit_set(target, {"a.bin"}, error)) << error;
  EXPECT_TRUE(fs::exists(live.staging_path())) << "a live writer's staging was removed";
}

TEST_F(StagedDirectoryTest, ASymbolicLinkKeepsPointingAtTheNewSet) {
  const fs::path real = scratch_.path() / "real";
  const fs::path link = scratch_.path() / "link";
  fs::create_directory(real);
  fs::create_directory_symlink(real, link);
  std::string error;
  ASSERT_TRUE(commit_set(link, {"a.bin"}, error)) << error;
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_TRUE(fs::exists(real / "a.bin"));
}

}  // namespace
}  // namespace oasis
