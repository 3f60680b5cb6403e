#include "support/atomic_file.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <unistd.h>

#include "../support/scratch_directory.hpp"

namespace oasis {
namespace {

namespace fs = std::filesystem;

// A fresh, empty directory per test, removed afterwards.
class AtomicFileTest : public ::testing::Test {
 protected:
  test::ScratchDirectory scratch_{"oasis_atomic"};
  const std::filesystem::path& directory_ = scratch_.path();

  [[nodiscard]] std::size_t entries() const {
    return static_cast<std::size_t>(
        std::distance(fs::directory_iterator(directory_), fs::directory_iterator()));
  }
  [[nodiscard]] std::string target() const { return (directory_ / "out.txt").string(); }

  static std::string contents(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }
};

TEST_F(AtomicFileTest, NothingAppearsBeforeCommit) {
  AtomicFile file;
  std::string error;
  ASSERT_TRUE(file.open(target(), error)) << error;
  file.append("hello ");
  file.append_number(42);
  file.append(' ');
  file.append_number(-7LL);
  file.append('\n');
  EXPECT_FALSE(fs::exists(target()));
  EXPECT_TRUE(fs::exists(file.temporary_path()));
  EXPECT_EQ(fs::path(file.temporary_path()).parent_path(), directory_);
  ASSERT_TRUE(file.commit(error)) << error;
  EXPECT_EQ(contents(target()), "hello 42 -7\n");
  EXPECT_EQ(entries(), 1U);  // the temporary file is gone: it became the target
}

TEST_F(AtomicFileTest, NothingLeftBehindWithoutCommit) {
  {
    AtomicFile file;
    std::string error;
    ASSERT_TRUE(file.open(target(), error)) << error;
    file.append("half a model");
  }
  EXPECT_EQ(entries(), 0U);
}

TEST_F(AtomicFileTest, ExistingFileSurvivesUntilCommit) {
  std::ofstream(target()) << "old\n";
  AtomicFile file;
  std::string error;
  ASSERT_TRUE(file.open(target(), error)) << error;
  file.append("new\n");
  EXPECT_EQ(contents(target()), "old\n");
  file.discard();
  EXPECT_EQ(contents(target()), "old\n");
  EXPECT_EQ(entries(), 1U);

  ASSERT_TRUE(file.open(target(), error)) << error;
  file.append("new\n");
  ASSERT_TRUE(file.commit(error)) << error;
  EXPECT_EQ(contents(target()), "new\n");
}

TEST_F(AtomicFileTest, LargeWritesCrossTheBuffer) {
  std::string expected;
  AtomicFile file;
  std::string error;
  ASSERT_TRUE(file.open(target(), error)) << error;
  for (std::uint32_t i = 0; i < 300000; ++i) {
    file.append_number(i);
    file.append(i % 7 == 0 ? "\n" : " ");
    expected += std::to_string(i) + (i % 7 == 0 ? "\n" : " ");
  }
  const std::string big(3 << 20, 'x');  // bigger than the buffer: written directly
  file.append(big);
  expected += big;
  ASSERT_TRUE(file.commit(error)) << error;
  EXPECT_EQ(contents(target()), expected);
}

// A device is written, never replaced: renaming a temporary over /dev/null would turn the
// machine's /dev/null into a regular file (as root, which CI is).
TEST_F(AtomicFileTest, DeviceDestinationIsWrittenNotReplaced) {
  AtomicFile file;
  std::string error;
  ASSERT_TRUE(file.open("/dev/null", error)) << error;
  EXPECT_TRUE(file.temporary_path().empty());
  file.append("discarded by the device\n");
  ASSERT_TRUE(file.commit(error)) << error;
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
  EXPECT_FALSE(fs::exists("/dev/.null.tmp.0"));
}

TEST_F(AtomicFileTest, OpenInMissingDirectoryFails) {
  AtomicFile file;
  std::string error;
  EXPECT_FALSE(file.open((directory_ / "missing" / "out.txt").string(), error));
  EXPECT_NE(error.find("cannot create a temporary file"), std::string::npos) << error;
  EXPECT_NE(error.find("no such file or directory"), std::string::npos) << error;
  file.append("ignored");  // harmless when not open
  EXPECT_FALSE(file.commit(error));
}

TEST_F(AtomicFileTest, FailedRenameRemovesTemporary) {
  fs::create_directories(directory_ / "occupied" / "child");  // a non-empty directory
  AtomicFile file;
  std::string error;
  ASSERT_TRUE(file.open((directory_ / "occupied").string(), error)) << error;
  file.append("data");
  EXPECT_FALSE(file.commit(error));
  EXPECT_NE(error.find("cannot rename"), std::string::npos) << error;
  EXPECT_EQ(entries(), 1U);  // only the directory
}

TEST_F(AtomicFileTest, MoveKeepsOwnership) {
  std::string error;
  AtomicFile first;
  ASSERT_TRUE(first.open(target(), error)) << error;
  first.append("moved\n");
  AtomicFile second(std::move(first));
  first.discard();  // must not touch the moved-to temporary file
  ASSERT_TRUE(second.commit(error)) << error;
  EXPECT_EQ(contents(target()), "moved\n");
}

}  // namespace
}  // namespace oasis
