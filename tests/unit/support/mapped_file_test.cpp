// A mapped input that shrinks while it is read (issue 37, item 8): a read past its new end is
// "PATH: error: the file changed size while being read" and status 1, with the unfinished
// output removed, instead of a SIGBUS that kills the program. A SIGBUS anywhere else still
// kills it as before. Each case maps a file, cuts it with truncate(2) and then reads: the order
// is fixed, so nothing depends on timing. The reads run in a death test's child process.

#include "support/mapped_file.hpp"

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

#include "../../support/scratch_directory.hpp"
#include "support/interrupt_cleanup.hpp"
#include "support/source_manager.hpp"

namespace oasis {
namespace {

namespace fs = std::filesystem;

const std::size_t kPage = static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));

class MappedFileShrinkTest : public ::testing::Test {
 protected:
  // The death tests fork ("fast" style), so that the child's files are the parent's.
  MappedFileShrinkTest() : scratch_("oasis_mapped_file_test") {}

  // A file of `pages` pages of text, and its path.
  [[nodiscard]] std::string write_pages(const std::string& name, std::size_t pages) const {
    const fs::path path = scratch_.path() / name;
    std::ofstream(path, std::ios::binary) << std::string(pages * kPage, 'x');
    return path.string();
  }

  test::ScratchDirectory scratch_;
};

// Reads every byte, so that a read past the end of the file faults.
std::size_t count_x(std::string_view text) {
  std::size_t count = 0;
  for (const char c : text)
    count += c == 'x' ? 1 : 0;
  return count;
}

TEST_F(MappedFileShrinkTest, AReadPastTheNewEndIsAnErrorNamingTheFile) {
  const std::string path = write_pages("model.aut", 4);
  EXPECT_EXIT(
      {
        MappedFile file;
        std::string error;
        if (!file.open(path, SIZE_MAX, error)) std::_Exit(3);
        if (::truncate(path.c_str(), static_cast<off_t>(kPage)) != 0) std::_Exit(4);
        std::_Exit(count_x(file.text()) > 0 ? 5 : 6);  // never reached: page 2 is gone
      },
      ::testing::ExitedWithCode(1),
      "^[^\n]*model\\.aut: error: the file changed size while being read\n$");
}

TEST_F(MappedFileShrinkTest, TheUnfinishedOutputIsRemoved) {
  const std::string path = write_pages("spec.oasis", 2);
  const fs::path staged = scratch_.path() / "out.staging";
  fs::create_directory(staged);
  std::ofstream(staged / "half.bin") << "half a catalog";
  EXPECT_EXIT(
      {
        const interrupt::CleanupPath cleanup(staged.string(),
                                             interrupt::CleanupPath::Kind::kDirectory);
        MappedFile file;
        std::string error;
        if (!file.open(path, SIZE_MAX, error)) std::_Exit(3);
        if (::truncate(path.c_str(), 0) != 0) std::_Exit(4);
        std::_Exit(count_x(file.text()) > 0 ? 5 : 6);
      },
      ::testing::ExitedWithCode(1), "spec\\.oasis: error: the file changed size while being read");
  EXPECT_FALSE(fs::exists(staged));
}

TEST_F(MappedFileShrinkTest, TheNoteSaysWhichProcessRead) {
  const std::string path = write_pages("big.aut", 2);
  EXPECT_EXIT(
      {
        set_changed_size_note(" (rank 3)");
        MappedFile file;
        std::string error;
        if (!file.open(path, SIZE_MAX, error)) std::_Exit(3);
        if (::truncate(path.c_str(), 0) != 0) std::_Exit(4);
        std::_Exit(count_x(file.text()) > 0 ? 5 : 6);
      },
      ::testing::ExitedWithCode(1),
      "big\\.aut: error: the file changed size while being read \\(rank 3\\)\n$");
}

// Through SourceManager, as every reader gets its file: the test hook cuts the file once it is
// the reader's, before the reader reads.
TEST_F(MappedFileShrinkTest, TheTestHookCutsAFileAddedToTheSources) {
  const std::string path = write_pages("hooked.aut", 3);
  EXPECT_EXIT(
      {
        ::setenv("OASIS_TEST_SHRINK_INPUT", "0", 1);
        MappedFile file;
        std::string error;
        if (!file.open(path, SIZE_MAX, error)) std::_Exit(3);
        SourceManager sources;
        const FileId id = sources.add(path, std::move(file));
        std::_Exit(count_x(sources.file(id).text()) > 0 ? 5 : 6);
      },
      ::testing::ExitedWithCode(1), "hooked\\.aut: error: the file changed size while being read");
}

TEST_F(MappedFileShrinkTest, AFileThatKeepsItsSizeIsReadWhole) {
  const std::string path = write_pages("whole.aut", 3);
  ::setenv("OASIS_TEST_SHRINK_INPUT", "5000000", 1);  // longer than the file: nothing to cut
  MappedFile file;
  std::string error;
  ASSERT_TRUE(file.open(path, SIZE_MAX, error)) << error;
  SourceManager sources;
  const FileId id = sources.add(path, std::move(file));
  ::unsetenv("OASIS_TEST_SHRINK_INPUT");
  EXPECT_EQ(count_x(sources.file(id).text()), 3 * kPage);
  EXPECT_EQ(fs::file_size(path), 3 * kPage);
}

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kAddressSanitizer = true;
#else
constexpr bool kAddressSanitizer = false;
#endif
#else
constexpr bool kAddressSanitizer = false;
#endif

// What a SIGBUS that is not ours does: whatever the handler before ours did. In a plain build
// that is the default, death by the signal; under AddressSanitizer, whose handler was there
// first, its report ("AddressSanitizer: BUS"), then its exit: status 1, or SIGABRT with
// abort_on_error as the asan test preset sets it.
bool ended_as_the_previous_handler_ends(int status) {
  if (kAddressSanitizer)
    return (WIFEXITED(status) && WEXITSTATUS(status) == 1) ||
           (WIFSIGNALED(status) && WTERMSIG(status) == SIGABRT);
  return WIFSIGNALED(status) && WTERMSIG(status) == SIGBUS;
}
constexpr const char* kPreviousHandlerSays = kAddressSanitizer ? "AddressSanitizer" : "";

// A fault outside every registered mapping (here a mapping of our own making) is not ours:
// the program dies of SIGBUS as it would without the handler.
TEST_F(MappedFileShrinkTest, AFaultElsewhereStillKillsTheProgram) {
  const std::string watched = write_pages("watched.aut", 2);
  const std::string other = write_pages("other.bin", 2);
  EXPECT_EXIT(
      {
        MappedFile file;  // installs the handler
        std::string error;
        if (!file.open(watched, SIZE_MAX, error)) std::_Exit(3);
        const int fd = ::open(other.c_str(), O_RDONLY);
        void* raw = ::mmap(nullptr, 2 * kPage, PROT_READ, MAP_PRIVATE, fd, 0);
        if (raw == MAP_FAILED || ::truncate(other.c_str(), 0) != 0) std::_Exit(4);
        std::_Exit(count_x({static_cast<const char*>(raw), 2 * kPage}) > 0 ? 5 : 6);
      },
      ended_as_the_previous_handler_ends, kPreviousHandlerSays);
}

// A SIGBUS sent by another process is no fault in a file: it kills as before.
TEST_F(MappedFileShrinkTest, ASentSigbusStillKillsTheProgram) {
  const std::string watched = write_pages("sent.aut", 1);
  EXPECT_EXIT(
      {
        MappedFile file;
        std::string error;
        if (!file.open(watched, SIZE_MAX, error)) std::_Exit(3);
        ::kill(::getpid(), SIGBUS);
        std::_Exit(5);
      },
      ended_as_the_previous_handler_ends, kPreviousHandlerSays);
}

}  // namespace
}  // namespace oasis
