// Nothing lost through -o: the tools write what a plain open() would reach and replace only
// regular files. A symbolic link's target is replaced in its own directory (the link stays),
// a named pipe is written to its reader, a device is written (never replaced), and `-o -`
// is standard output, for every command that takes -o.

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include "../../support/run_oasisc.hpp"
#include "../../support/scratch_directory.hpp"

namespace oasis {
namespace {

namespace fs = std::filesystem;
using test::run_oasisc;

const std::string kSpec = std::string(OASIS_SOURCE_DIR) + "/specs/discrete_tracking.oasis";
const std::string kAut = std::string(OASIS_SOURCE_DIR) + "/tests/data/formats/coin.aut";

std::string contents(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string quoted(const fs::path& path) {
  return "'" + path.string() + "'";
}

// Names in `directory` that look like a writer's temporary file or staging directory.
std::size_t temporaries_in(const fs::path& directory) {
  std::size_t count = 0;
  for (const auto& entry : fs::directory_iterator(directory)) {
    const std::string name = entry.path().filename().string();
    if (name.find(".tmp.") != std::string::npos || name.find("-staging.") != std::string::npos)
      ++count;
  }
  return count;
}

class SpecialOutput : public ::testing::Test {
 protected:
  test::ScratchDirectory scratch_{"oasis_special_output"};
  const fs::path& directory_ = scratch_.path();
};

TEST_F(SpecialOutput, SymbolicLinkTargetIsReplacedAndTheLinkStays) {
  fs::create_directories(directory_ / "results");
  const fs::path real = directory_ / "results" / "quotient.json";
  std::ofstream(real) << "stale\n";
  const fs::path link = directory_ / "latest.json";
  fs::create_symlink("results/quotient.json", link);

  const auto result = run_oasisc("quotient " + kSpec + " --format json -o " + quoted(link));
  ASSERT_EQ(result.status, 0) << result.output;
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_EQ(fs::read_symlink(link), "results/quotient.json");
  EXPECT_NE(contents(real).find("\"contexts\""), std::string::npos) << contents(real);
  EXPECT_EQ(temporaries_in(directory_), 0U);
  EXPECT_EQ(temporaries_in(directory_ / "results"), 0U);
}

TEST_F(SpecialOutput, ExportThroughASymbolicLink) {
  const fs::path real = directory_ / "model.aut";
  std::ofstream(real) << "stale\n";
  const fs::path link = directory_ / "current.aut";
  fs::create_symlink(real, link);
  const auto result =
      run_oasisc("export " + kSpec + " --context object_at_s1 --format aut -o " + quoted(link));
  ASSERT_EQ(result.status, 0) << result.output;
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_EQ(contents(real).rfind("des (", 0), 0U) << contents(real);
}

TEST_F(SpecialOutput, CompileIntoASymbolicLinkToADirectory) {
  fs::create_directories(directory_ / "catalogs");
  const fs::path link = directory_ / "catalog";
  fs::create_directory_symlink("catalogs/tracking", link);  // dangling until the compile
  const auto result =
      run_oasisc("compile " + kSpec + " --format bin --progress never -o " + quoted(link));
  ASSERT_EQ(result.status, 0) << result.output;
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_TRUE(fs::exists(directory_ / "catalogs" / "tracking" / "discrete_tracking.bin"));
  EXPECT_EQ(temporaries_in(directory_ / "catalogs"), 0U);
}

// The reader of a named pipe gets the whole file, and the pipe is still a pipe.
TEST_F(SpecialOutput, NamedPipeReaderGetsTheOutput) {
  const fs::path fifo = directory_ / "quotient.pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::string received;
  std::thread reader([&] { received = contents(fifo); });
  const auto result = run_oasisc("quotient " + kSpec + " --format json -o " + quoted(fifo));
  // Had oasisc never opened the pipe, this open would release the blocked reader.
  const int release = ::open(fifo.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC);
  if (release >= 0) ::close(release);
  reader.join();
  EXPECT_EQ(result.status, 0) << result.output;
  EXPECT_NE(received.find("\"contexts\""), std::string::npos) << received;
  EXPECT_EQ(fs::status(fifo).type(), fs::file_type::fifo);
  EXPECT_EQ(temporaries_in(directory_), 0U);
}

TEST_F(SpecialOutput, DevNullStaysADevice) {
  for (const std::string& command : {"quotient " + kSpec + " --format json -o /dev/null",
                                     "export " + kAut + " --format aut -o /dev/null"}) {
    const auto result = run_oasisc(command);
    EXPECT_EQ(result.status, 0) << command << "\n" << result.output;
    EXPECT_TRUE(fs::is_character_file("/dev/null"));
  }
}

TEST_F(SpecialOutput, FullDeviceIsAnError) {
  const auto result = run_oasisc("export " + kAut + " --format aut -o /dev/full");
  EXPECT_EQ(result.status, 1) << result.output;
  EXPECT_NE(result.output.find("no space left on device"), std::string::npos) << result.output;
  EXPECT_TRUE(fs::is_character_file("/dev/full"));
}

// `-o -` is standard output for every command with -o; its report goes to stderr.
TEST_F(SpecialOutput, DashIsStandardOutput) {
  const fs::path out = directory_ / "stdout";
  const std::string to_file = " 2>/dev/null >" + quoted(out);

  ASSERT_EQ(run_oasisc("quotient " + kSpec + " --format json -o -" + to_file).status, 0);
  EXPECT_EQ(contents(out).rfind("{", 0), 0U) << contents(out);

  ASSERT_EQ(run_oasisc("quotient " + kSpec + " --context object_at_s1 --format aut -o -" + to_file)
                .status,
            0);
  EXPECT_EQ(contents(out).rfind("des (", 0), 0U) << contents(out);

  ASSERT_EQ(run_oasisc("export " + kAut + " --format aut -o -" + to_file).status, 0);
  ASSERT_EQ(
      run_oasisc("export " + kAut + " --format aut -o " + quoted(directory_ / "coin.aut")).status,
      0);
  EXPECT_EQ(contents(out), contents(directory_ / "coin.aut"));
  EXPECT_EQ(contents(out).rfind("des (", 0), 0U) << contents(out);

  // compile: the binary catalog on stdout is the very file a compile into a folder writes.
  ASSERT_EQ(run_oasisc("compile " + kSpec + " --format bin --progress never -o -" + to_file).status,
            0);
  ASSERT_EQ(run_oasisc("compile " + kSpec + " --format bin --progress never -o " +
                       quoted(directory_ / "folder"))
                .status,
            0);
  EXPECT_EQ(contents(out), contents(directory_ / "folder" / "discrete_tracking.bin"));
  EXPECT_EQ(temporaries_in(directory_), 0U);
}

TEST_F(SpecialOutput, DashRefusesWhatIsSeveralFiles) {
  const struct {
    std::string command;
    std::string message;
  } cases[] = {
      {"compile " + kSpec + " -o -", "choose one --format"},
      {"compile " + kSpec + " --format cpp -o -", "cpp"},
      {"compile " + kSpec + " --format dot -o -", "one per context (2 here)"},
      {"export " + kAut + " --format prism -o -", "--format prism writes several files"},
      {"quotient " + kSpec + " --format aut -o -", "choose one with --context"},
  };
  for (const auto& c : cases) {
    const auto result = run_oasisc(c.command + " > /dev/null");
    EXPECT_NE(result.status, 0) << c.command;
    EXPECT_NE(result.output.find(c.message), std::string::npos) << c.command << "\n"
                                                                << result.output;
  }
}

TEST_F(SpecialOutput, FitFragmentToDashIsPrintedOnce) {
  const std::string data = std::string(OASIS_SOURCE_DIR) + "/tests/data/fit/";
  const auto result = run_oasisc("fit switching " + data + "tracking.oasis " + data +
                                 "switching_log.csv --progress never -o -");
  ASSERT_EQ(result.status, 0) << result.output;
  const std::size_t first = result.output.find("switching stay");
  ASSERT_NE(first, std::string::npos) << result.output;
  EXPECT_EQ(result.output.find("switching stay", first + 1), std::string::npos) << result.output;
  EXPECT_EQ(result.output.find("wrote"), std::string::npos) << result.output;
}

}  // namespace
}  // namespace oasis
