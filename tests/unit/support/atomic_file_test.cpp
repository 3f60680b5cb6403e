#include "support/atomic_file.hpp"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <thread>

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include "../../support/scratch_directory.hpp"

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
  // The temporary file is anonymous (O_TMPFILE) or a hidden sibling of the destination.
  if (!file.temporary_path().empty()) {
    EXPECT_TRUE(fs::exists(file.temporary_path()));
    EXPECT_EQ(fs::path(file.temporary_path()).parent_path(), directory_);
  }
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

// A link is followed: the file it names is replaced in its own directory (no temporary is
// left there or beside the link) and the link stays a link.
TEST_F(AtomicFileTest, SymbolicLinkReplacesItsTargetAndStaysALink) {
  fs::create_directories(directory_ / "real");
  fs::create_directories(directory_ / "links");
  const fs::path real = directory_ / "real" / "catalog.json";
  std::ofstream(real) << "old\n";
  const fs::path link = directory_ / "links" / "catalog.json";
  fs::create_symlink("../real/catalog.json", link);  // relative, as users make them
  const fs::path link_to_link = directory_ / "latest.json";
  fs::create_symlink(link, link_to_link);

  AtomicFile file;
  std::string error;
  ASSERT_TRUE(file.open(link_to_link.string(), error)) << error;
  EXPECT_EQ(fs::path(file.destination()).filename(), "catalog.json");
  EXPECT_EQ(fs::canonical(fs::path(file.destination()).parent_path()), directory_ / "real");
  file.append("new\n");
  ASSERT_TRUE(file.commit(error)) << error;

  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_TRUE(fs::is_symlink(link_to_link));
  EXPECT_EQ(fs::read_symlink(link), "../real/catalog.json");
  EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(real)));
  EXPECT_EQ(contents(real.string()), "new\n");
  EXPECT_EQ(contents(link_to_link.string()), "new\n");
  for (const fs::path& folder : {directory_, directory_ / "real", directory_ / "links"}) {
    for (const auto& entry : fs::directory_iterator(folder))
      EXPECT_EQ(entry.path().filename().string().find(".tmp."), std::string::npos) << entry.path();
  }
}

// A dangling link names the file to create, as a plain open() through it would.
TEST_F(AtomicFileTest, DanglingLinkCreatesItsTarget) {
  const fs::path link = directory_ / "out.aut";
  fs::create_symlink("made.aut", link);
  AtomicFile file;
  std::string error;
  ASSERT_TRUE(file.open(link.string(), error)) << error;
  file.append("des (0,0,1)\n");
  ASSERT_TRUE(file.commit(error)) << error;
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_EQ(contents((directory_ / "made.aut").string()), "des (0,0,1)\n");
  EXPECT_EQ(entries(), 2U);
}

TEST_F(AtomicFileTest, LinkLoopIsAnError) {
  fs::create_symlink("b", directory_ / "a");
  fs::create_symlink("a", directory_ / "b");
  AtomicFile file;
  std::string error;
  EXPECT_FALSE(file.open((directory_ / "a").string(), error));
  EXPECT_NE(error.find("too many levels of symbolic links"), std::string::npos) << error;
}

TEST_F(AtomicFileTest, ReplacedFileKeepsItsPermissions) {
  std::ofstream(target()) << "#!/bin/sh\n";
  fs::permissions(target(), fs::perms::owner_all | fs::perms::group_read);
  AtomicFile file;
  std::string error;
  ASSERT_TRUE(file.open(target(), error)) << error;
  file.append("#!/bin/sh\necho new\n");
  ASSERT_TRUE(file.commit(error)) << error;
  EXPECT_EQ(fs::status(target()).permissions(), fs::perms::owner_all | fs::perms::group_read);
}

// A named pipe is written, not replaced: the reader gets every byte.
TEST_F(AtomicFileTest, FifoIsWrittenToItsReader) {
  const fs::path fifo = directory_ / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::string received;
  std::thread reader([&] { received = contents(fifo.string()); });
  std::string expected;
  {
    AtomicFile file;
    std::string error;
    // Blocks until the reader opens. No ASSERT here: the reader must be joined below.
    EXPECT_TRUE(file.open(fifo.string(), error)) << error;
    EXPECT_TRUE(file.writes_directly());
    for (int line = 0; line < 100000; ++line) {  // more than the pipe and the buffer hold
      file.append_number(line);
      file.append('\n');
      expected += std::to_string(line) + "\n";
    }
    EXPECT_TRUE(file.commit(error)) << error;
  }
  // Had the writer never opened the pipe, this open would release the blocked reader.
  const int release = ::open(fifo.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC);
  if (release >= 0) ::close(release);
  reader.join();
  EXPECT_EQ(received, expected);
  EXPECT_EQ(fs::status(fifo).type(), fs::file_type::fifo);
  EXPECT_EQ(entries(), 1U);
}

// "-" and /dev/stdout write to the process's standard output, after what std::cout holds,
// and leave it open (the tools check it once more at exit).
TEST_F(AtomicFileTest, DashAndDevStdoutWriteStandardOutput) {
  for (const std::string name : {"-", "/dev/stdout", "/dev/fd/1"}) {
    const fs::path captured = directory_ / "stdout.txt";
    std::cout.flush();
    const int saved = ::dup(STDOUT_FILENO);
    const int capture = ::open(captured.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
    ASSERT_GE(capture, 0);
    ::dup2(capture, STDOUT_FILENO);
    ::close(capture);
    std::cout << "before ";
    AtomicFile file;
    std::string error;
    const bool opened = file.open(name, error);
    file.append("data");
    const bool committed = file.commit(error);
    std::cout << " after\n" << std::flush;
    const bool still_open = ::fcntl(STDOUT_FILENO, F_GETFD) != -1;
    ::dup2(saved, STDOUT_FILENO);
    ::close(saved);
    EXPECT_TRUE(opened && committed) << name << ": " << error;
    EXPECT_TRUE(file.writes_directly()) << name;
    EXPECT_TRUE(still_open) << name;
    // The file the shell redirected to is written through its descriptor, never replaced.
    EXPECT_EQ(contents(captured.string()), "before data after\n") << name;
    EXPECT_EQ(entries(), 1U) << name;
  }
}

TEST_F(AtomicFileTest, FullDeviceIsAnError) {
  AtomicFile file;
  std::string error;
  ASSERT_TRUE(file.open("/dev/full", error)) << error;
  file.append("no room\n");
  EXPECT_FALSE(file.commit(error));
  EXPECT_NE(error.find("no space left on device"), std::string::npos) << error;
  EXPECT_TRUE(fs::is_character_file("/dev/full"));
}

// A writer killed after creating a named temporary file leaves it behind; the next writer
// of the same destination removes it (its flock is free), but never a live writer's.
TEST_F(AtomicFileTest, StaleTemporaryOfAKilledWriterIsRemoved) {
  const fs::path stale = directory_ / ".out.txt.tmp.killed0001";
  std::ofstream(stale) << "half";
  AtomicFile live;
  std::string error;
  ASSERT_TRUE(live.open(target(), error)) << error;
  AtomicFile next;
  ASSERT_TRUE(next.open(target(), error)) << error;
  EXPECT_FALSE(fs::exists(stale));
  next.append("next\n");
  ASSERT_TRUE(next.commit(error)) << error;
  live.append("live\n");
  ASSERT_TRUE(live.commit(error)) << error;  // its temporary file was not taken for stale
  EXPECT_EQ(contents(target()), "live\n");
  EXPECT_EQ(entries(), 1U);
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
