// AtomicFileSet (support/atomic_file_set.hpp): several files that change as one unit. When one
// destination cannot be replaced, every file stays as it was; `oasisc export --format prism`
// and `quotient --format aut` with several contexts keep their old set whole the same way
// (issue 28: a .tra from one spec beside an .srew from another).

#include "support/atomic_file_set.hpp"

#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "../../support/file_snapshot.hpp"
#include "../../support/run_oasisc.hpp"
#include "../../support/scratch_directory.hpp"

namespace oasis {
namespace {

namespace fs = std::filesystem;
using test::Files;
using test::snapshot;

bool write_set(const fs::path& directory, const std::string& text, std::string& error) {
  AtomicFileSet set;
  for (const char* name : {"a.txt", "b.txt", "c.txt"}) {
    AtomicFile* file = set.add((directory / name).string(), error);
    if (file == nullptr) return false;
    file->append(text + " " + name);
  }
  return set.commit(error);
}

TEST(AtomicFileSet, CommitsEveryFileOrNone) {
  const test::ScratchDirectory scratch("oasis_file_set");
  std::string error;
  ASSERT_TRUE(write_set(scratch.path(), "old", error)) << error;
  const Files old_set = snapshot(scratch.path());
  ASSERT_EQ(old_set.size(), 3U);
  EXPECT_EQ(old_set.at("b.txt"), "old b.txt");

  // c.txt cannot be replaced (it became a directory): a.txt and b.txt stay old too.
  fs::remove(scratch.path() / "c.txt");
  fs::create_directory(scratch.path() / "c.txt");
  std::ofstream(scratch.path() / "c.txt" / "inside") << "user data";
  Files before = snapshot(scratch.path());
  EXPECT_FALSE(write_set(scratch.path(), "new", error));
  EXPECT_NE(error.find("c.txt"), std::string::npos) << error;
  EXPECT_EQ(snapshot(scratch.path()), before);  // and no temporary file left
  EXPECT_TRUE(fs::exists(scratch.path() / "c.txt" / "inside"));

  fs::remove_all(scratch.path() / "c.txt");
  ASSERT_TRUE(write_set(scratch.path(), "new", error)) << error;
  const Files new_set = snapshot(scratch.path());
  EXPECT_EQ(new_set.size(), 3U);
  EXPECT_EQ(new_set.at("a.txt"), "new a.txt");
}

TEST(AtomicFileSet, RemovesAStaleSiblingOnlyWhenItCommits) {
  const test::ScratchDirectory scratch("oasis_file_set_remove");
  std::ofstream(scratch.path() / "model.sta") << "stale";
  std::string error;
  {
    AtomicFileSet set;
    AtomicFile* file = set.add((scratch.path() / "model.tra").string(), error);
    ASSERT_NE(file, nullptr) << error;
    file->append("rows");
    set.remove_at_commit((scratch.path() / "model.sta").string());
    set.discard();
  }
  EXPECT_TRUE(fs::exists(scratch.path() / "model.sta"));
  EXPECT_FALSE(fs::exists(scratch.path() / "model.tra"));
  AtomicFileSet set;
  AtomicFile* file = set.add((scratch.path() / "model.tra").string(), error);
  ASSERT_NE(file, nullptr) << error;
  file->append("rows");
  set.remove_at_commit((scratch.path() / "model.sta").string());
  ASSERT_TRUE(set.commit(error)) << error;
  EXPECT_EQ(snapshot(scratch.path()), (Files{{"model.tra", "rows"}}));
}

// The case: exporting another model over a PRISM set whose .srew cannot be replaced
// used to leave the new .tra and .lab beside the old rewards.
TEST(AtomicFileSet, PrismExportKeepsTheOldSetWhole) {
  const test::ScratchDirectory scratch("oasis_prism_set");
  const std::string source = OASIS_SOURCE_DIR;
  const std::string base = (scratch.path() / "model").string();
  const auto first = test::run_oasisc("export '" + source +
                                      "/specs/discrete_tracking.oasis' --context object_at_s1 "
                                      "--format prism -o '" +
                                      base + "'");
  ASSERT_EQ(first.status, 0) << first.output;
  fs::remove(base + ".srew");
  fs::create_directory(base + ".srew");
  const Files before = snapshot(scratch.path());
  ASSERT_EQ(before.count("model.tra"), 1U);

  const auto second = test::run_oasisc(
      "export '" + source + "/tests/data/formats/robot.tra' --format prism -o '" + base + "'");
  EXPECT_EQ(second.status, 1) << second.output;
  EXPECT_NE(second.output.find("model.srew"), std::string::npos) << second.output;
  EXPECT_EQ(snapshot(scratch.path()), before);
}

TEST(AtomicFileSet, QuotientOfSeveralContextsKeepsTheOldFilesWhole) {
  const test::ScratchDirectory scratch("oasis_quotient_set");
  const std::string spec = std::string(OASIS_SOURCE_DIR) + "/specs/discrete_tracking.oasis";
  const std::string out = (scratch.path() / "q.aut").string();
  const auto first = test::run_oasisc("quotient '" + spec + "' --format aut -o '" + out + "'");
  ASSERT_EQ(first.status, 0) << first.output;
  const Files written = snapshot(scratch.path());
  ASSERT_GE(written.size(), 2U);  // one file per context
  // One context's file becomes a directory: the next quotient must change none of the others.
  const std::string victim = written.rbegin()->first;
  fs::remove(scratch.path() / victim);
  fs::create_directory(scratch.path() / victim);
  for (auto& [name, bytes] : snapshot(scratch.path()))
    std::ofstream(scratch.path() / name, std::ios::binary) << "old " << name;
  const Files before = snapshot(scratch.path());
  const auto second = test::run_oasisc("quotient '" + spec + "' --format aut -o '" + out + "'");
  EXPECT_EQ(second.status, 1) << second.output;
  EXPECT_EQ(snapshot(scratch.path()), before);
}

}  // namespace
}  // namespace oasis
