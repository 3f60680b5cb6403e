// The readers' one rule (common/files/input_file.hpp), which every program's file readers use:
// a regular file is read, a pipe once its writer delivers, and a directory, a device or a pipe
// nobody writes to is refused with what it is, never waited on forever.

#include "files/input_file.hpp"

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include "../../support/scratch_directory.hpp"

namespace oasis {
namespace {

namespace fs = std::filesystem;

TEST(InputFile, ARegularFileIsReadWhole) {
  const test::ScratchDirectory scratch("oasis_input_file");
  const std::string path = (scratch.path() / "a.txt").string();
  std::ofstream(path) << "three words here";
  std::string reason;
  EXPECT_EQ(files::read_input(path, 100, reason), "three words here");
  EXPECT_FALSE(files::read_input(path, 5, reason));
  EXPECT_EQ(reason, "is larger than the limit of 5 bytes");
}

TEST(InputFile, WhatIsNotAFileIsNamed) {
  const test::ScratchDirectory scratch("oasis_input_kinds");
  std::string reason;
  EXPECT_FALSE(files::read_input(scratch.path().string(), 100, reason));
  EXPECT_EQ(reason, "is a directory");
  EXPECT_FALSE(files::read_input("/dev/null", 100, reason));
  EXPECT_EQ(reason, "is a device, not a file");
  EXPECT_FALSE(files::read_input((scratch.path() / "missing").string(), 100, reason));
  EXPECT_EQ(reason, "no such file or directory");
}

TEST(InputFile, APipeIsReadOnceItsWriterWrites) {
  const test::ScratchDirectory scratch("oasis_input_pipe");
  const std::string fifo = (scratch.path() / "pipe").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::thread writer([&fifo] {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    std::ofstream(fifo) << "through the pipe";
  });
  std::string reason;
  EXPECT_EQ(files::read_input(fifo, 100, reason), "through the pipe") << reason;
  writer.join();
}

TEST(InputFile, APipeNobodyWritesToIsRefusedAfterItsGrace) {
  const test::ScratchDirectory scratch("oasis_input_silent");
  const std::string fifo = (scratch.path() / "silent").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::string reason;
  EXPECT_FALSE(files::read_input(fifo, 100, reason));
  EXPECT_EQ(reason.rfind("is a pipe that nobody writes to", 0), 0U) << reason;
}

}  // namespace
}  // namespace oasis
