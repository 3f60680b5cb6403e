// End-to-end tests of the oasisc command line: exit statuses, JSON output, help, and the
// errors for files that cannot be read.

#include <array>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sys/wait.h>
#include <unistd.h>

#include "../../support/catalog_bytes.hpp"
#include "../../support/run_oasisc.hpp"
#include "../../support/scratch_directory.hpp"
#include "oasis/rt/catalog_file.hpp"

namespace {

using Result = oasis::test::CommandResult;

Result run(const std::string& arguments) {
  return oasis::test::run_oasisc(arguments);
}

std::string spec(const std::string& name) {
  return std::string(OASIS_SOURCE_DIR) + "/specs/" + name;
}

// Each test's files go in its own scratch directory, removed when the test ends (also when
// an assertion ends it early).
class Cli : public ::testing::Test {
 protected:
  [[nodiscard]] std::filesystem::path write_temp(const std::string& name,
                                                 const std::string& text) const {
    const auto path = scratch_.path() / name;
    std::ofstream(path) << text;
    return path;
  }

  oasis::test::ScratchDirectory scratch_{"oasis_cli_test"};
};

TEST_F(Cli, InfoJsonOnDiscreteTracking) {
  const Result result = run("info --json " + spec("discrete_tracking.oasis"));
  ASSERT_EQ(result.status, 0) << result.output;
  const auto json = nlohmann::json::parse(result.output);
  EXPECT_EQ(json["states"], 3);
  EXPECT_EQ(json["actions"], 2);
  ASSERT_EQ(json["contexts"].size(), 2U);
  EXPECT_EQ(json["contexts"][0]["name"], "object_at_s3");
  EXPECT_EQ(json["contexts"][1]["name"], "object_at_s1");
  for (const auto& context : json["contexts"]) {
    EXPECT_EQ(context["states"], 3);
    EXPECT_EQ(context["actions"], 2);
    EXPECT_EQ(context["transitions"], 10);  // 1+2+2 for L, 2+2+1 for R
  }
  EXPECT_EQ(json["switching"][0][0], "4/5");
  EXPECT_EQ(json["prior"][1], "1/2");
}

TEST_F(Cli, CheckShippedSpecsSucceeds) {
  const Result result =
      run("check " + spec("discrete_tracking.oasis") + " " + spec("go1_treat.oasis"));
  EXPECT_EQ(result.status, 0) << result.output;
  EXPECT_NE(result.output.find("discrete_tracking.oasis: ok"), std::string::npos);
}

TEST_F(Cli, ContinuousInfoHasNoFiniteStates) {
  const Result result = run("info --json " + spec("go1_treat.oasis"));
  ASSERT_EQ(result.status, 0) << result.output;
  const auto json = nlohmann::json::parse(result.output);
  EXPECT_TRUE(json["states"].is_null());
  EXPECT_EQ(json["continuous_variables"].size(), 4U);
  EXPECT_EQ(json["actions"], 6);
  EXPECT_EQ(json["contexts"].size(), 2U);
}

TEST_F(Cli, HelpOnEveryCommand) {
  for (const char* command : {"", "check ", "info "}) {
    const Result result = run(std::string(command) + "--help");
    EXPECT_EQ(result.status, 0) << command;
    EXPECT_NE(result.output.find("Usage"), std::string::npos) << command << result.output;
  }
}

TEST_F(Cli, BadUsageExitsWithTwo) {
  EXPECT_EQ(run("").status, 2);
  EXPECT_EQ(run("frobnicate").status, 2);
  EXPECT_EQ(run("check").status, 2);  // no files
  EXPECT_EQ(run("check --max-states 0 x.oasis").status, 2);
}

TEST_F(Cli, UnreadableFilesAreErrorsNotCrashes) {
  Result result = run("check /nonexistent/file.oasis");
  EXPECT_EQ(result.status, 1);
  EXPECT_NE(result.output.find("/nonexistent/file.oasis: error: cannot read spec: no such file"),
            std::string::npos)
      << result.output;

  result = run("check " + std::filesystem::temp_directory_path().string());
  EXPECT_EQ(result.status, 1);
  EXPECT_NE(result.output.find("is a directory"), std::string::npos) << result.output;

  // The readers' one rule (common/files/input_file.hpp): a device is no spec.
  result = run("check /dev/null");
  EXPECT_EQ(result.status, 1);
  EXPECT_NE(result.output.find("/dev/null: error: cannot read spec: is a device, not a file"),
            std::string::npos)
      << result.output;
}

TEST_F(Cli, SizeLimitIsAnError) {
  const Result result = run("check --max-spec-size 100 " + spec("discrete_tracking.oasis"));
  EXPECT_EQ(result.status, 1);
  EXPECT_NE(result.output.find("larger than the limit of 100 bytes"), std::string::npos)
      << result.output;
}

TEST_F(Cli, StateLimitIsAnError) {
  const auto path = write_temp("big.oasis",
                               "mdp big { var x : [0 .. 999]; actions up; default self;\n"
                               "  [up] x < 999 -> (x' = x + 1); }\n");
  const Result result = run("check --max-states 100 " + path.string());
  EXPECT_EQ(result.status, 1);
  EXPECT_NE(result.output.find("exploration passed the limit of 100 states"), std::string::npos)
      << result.output;
  std::filesystem::remove(path);
}

TEST_F(Cli, ErrorLimitStopsTheFlood) {
  std::string text = "mdp m { states a; actions go; a, go -> a;\n";
  for (int i = 0; i < 50; ++i)
    text += "  reward nowhere" + std::to_string(i) + " : 1;\n";
  text += "}\n";
  const auto path = write_temp("flood.oasis", text);
  const Result result = run("check --max-errors 5 " + path.string());
  EXPECT_EQ(result.status, 1);
  EXPECT_NE(result.output.find("too many errors emitted"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("5 errors in"), std::string::npos) << result.output;
  std::filesystem::remove(path);
}

TEST_F(Cli, OneBadFileDoesNotHideTheOthers) {
  const auto bad = write_temp("bad.oasis", "mdp m { states a; }\n");
  const Result result = run("check " + bad.string() + " " + spec("discrete_tracking.oasis"));
  EXPECT_EQ(result.status, 1);
  EXPECT_NE(result.output.find("discrete_tracking.oasis: ok"), std::string::npos) << result.output;
  std::filesystem::remove(bad);
}

}  // namespace

namespace {

using oasis::test::fix_checksum;
using oasis::test::section_offset;

TEST_F(Cli, CompileThenVerifyTheCatalog) {
  const auto dir = scratch_.path() / "compiled";
  Result result = run("compile " + spec("discrete_tracking.oasis") + " -o " + dir.string());
  ASSERT_EQ(result.status, 0) << result.output;
  for (const char* file :
       {"discrete_tracking.bin", "discrete_tracking.json", "discrete_tracking.object_at_s3.dot",
        "discrete_tracking.object_at_s1.dot"}) {
    EXPECT_TRUE(std::filesystem::exists(dir / file)) << file;
  }
  const auto catalog = dir / "discrete_tracking.bin";
  result = run("verify " + spec("discrete_tracking.oasis") + " " + catalog.string());
  EXPECT_EQ(result.status, 0) << result.output;
  EXPECT_NE(result.output.find("context object_at_s1: bisimulation and coarsest (2 blocks)"),
            std::string::npos);

  // A flipped byte: the checksum refuses the file.
  std::string bytes = oasis::test::read_bytes(catalog);
  std::string damaged = bytes;
  damaged[damaged.size() - 3] ^= 0x10;
  oasis::test::write_bytes(dir / "damaged.bin", damaged);
  result = run("verify " + spec("discrete_tracking.oasis") + " " + (dir / "damaged.bin").string());
  EXPECT_EQ(result.status, 1);
  EXPECT_NE(result.output.find("checksum mismatch"), std::string::npos) << result.output;

  // A well-formed file with the wrong partition (object_at_s1's in object_at_s3's place,
  // checksum recomputed): only the verifier can tell, and it does.
  const std::uint64_t offset = section_offset(bytes, oasis::rt::Section::kBlockOf, 0);
  ASSERT_NE(offset, 0U);
  const std::uint32_t swapped[3] = {0, 1, 1};
  std::memcpy(bytes.data() + offset, swapped, sizeof swapped);
  fix_checksum(bytes);
  oasis::test::write_bytes(dir / "swapped.bin", bytes);
  result = run("verify " + spec("discrete_tracking.oasis") + " " + (dir / "swapped.bin").string());
  EXPECT_EQ(result.status, 1) << result.output;
  EXPECT_NE(result.output.find("context object_at_s3: FAILED"), std::string::npos) << result.output;
}

}  // namespace

namespace {

// The compile of a discrete spec runs the shared pipeline with the refinement options of
// `quotient`: -j gives the same catalog as one thread, and --epsilon (a continuous option)
// is named as ignored rather than making a rounded catalog that verify would refuse.
TEST_F(Cli, DiscreteCompileTakesJobsAndExplainsEpsilon) {
  const auto& base = scratch_.path();
  const std::string input = spec("discrete_tracking.oasis");
  Result one = run("compile " + input + " --format bin -j 1 -o " + (base / "one").string());
  ASSERT_EQ(one.status, 0) << one.output;
  Result two =
      run("compile " + input + " --format bin -j 2 --epsilon 0.25 -o " + (base / "two").string());
  ASSERT_EQ(two.status, 0) << two.output;
  EXPECT_NE(two.output.find("warning: --epsilon is the error bound of continuous specs"),
            std::string::npos)
      << two.output;
  EXPECT_EQ(oasis::test::read_bytes(base / "one" / "discrete_tracking.bin"),
            oasis::test::read_bytes(base / "two" / "discrete_tracking.bin"));
  EXPECT_EQ(run("verify " + input + " " + (base / "two" / "discrete_tracking.bin").string()).status,
            0);
}

}  // namespace
