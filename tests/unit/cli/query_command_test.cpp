// `oasisc query` end to end: one line per property with its value and method, the exit
// statuses (0 answered, 1 an error in a property or the model, 2 bad usage), each error
// printed once, and a properties file read as PRISM writes them.

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>

#include "../../support/run_oasisc.hpp"
#include "../../support/scratch_directory.hpp"

namespace oasis {
namespace {

using test::run_oasisc;

const std::string kDie = std::string(OASIS_SOURCE_DIR) + "/tests/data/prism/knuth_die.pm";

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
    ++n;
  return n;
}

TEST(QueryCommand, AnswersEachPropertyOnOneLine) {
  const auto result =
      run_oasisc("query " + kDie + " --prop 'P=? [F node=7&face=1]' --prop 'P>=0.2 [F face=6]'");
  EXPECT_EQ(result.status, 0) << result.output;
  EXPECT_NE(result.output.find("P=? [F node=7&face=1] = 1/6 (about 0.1666666667)  [exact: "),
            std::string::npos)
      << result.output;
  EXPECT_NE(result.output.find("P>=0.2 [F face=6] is false in the initial state  [exact: "),
            std::string::npos)
      << result.output;
  EXPECT_EQ(count(result.output, "\n"), 2) << result.output;
}

TEST(QueryCommand, SoundModeGivesAnIntervalNarrowerThanThePrecision) {
  const auto result =
      run_oasisc("query " + kDie + " --mode sound --precision 1e-9 --prop 'P=? [F \"one\"]'");
  EXPECT_EQ(result.status, 0) << result.output;
  const std::size_t open = result.output.find(" in [");
  ASSERT_NE(open, std::string::npos) << result.output;
  const std::size_t comma = result.output.find(", ", open);
  const double lower = std::stod(result.output.substr(open + 5, comma - open - 5));
  const double upper = std::stod(result.output.substr(comma + 2));
  EXPECT_LE(lower, 1.0 / 6);
  EXPECT_GE(upper, 1.0 / 6);
  EXPECT_LE(upper - lower, 1e-9);
  EXPECT_NE(result.output.find("[sound: "), std::string::npos) << result.output;
}

TEST(QueryCommand, ABadPropertyIsOneLocatedErrorAndTheOthersAreStillAnswered) {
  const auto result = run_oasisc("query " + kDie + " --prop 'P=? [F \"seven\"]; P=? [F face=2]'");
  EXPECT_EQ(result.status, 1) << result.output;
  EXPECT_EQ(count(result.output, "error: unknown label \"seven\""), 1) << result.output;
  EXPECT_NE(result.output.find("--prop 1:1:8: error: unknown label"), std::string::npos)
      << result.output;
  EXPECT_NE(result.output.find("P=? [F face=2] = 1/6"), std::string::npos) << result.output;
}

TEST(QueryCommand, ReadsAPropertiesFile) {
  test::ScratchDirectory dir("query_command_test");
  const std::string props = (dir.path() / "die.props").string();
  std::ofstream(props)
      << "// the die\n\"one\": P=? [ F face=1 ]\n\"flips\": P=? [ F<=3 face=1 ];\n";
  const auto result = run_oasisc("query " + kDie + " --props " + props);
  EXPECT_EQ(result.status, 0) << result.output;
  EXPECT_NE(result.output.find("\"one\": P=? [ F face=1 ] = 1/6"), std::string::npos)
      << result.output;
  EXPECT_NE(result.output.find("\"flips\": P=? [ F<=3 face=1 ] = 1/8"), std::string::npos)
      << result.output;
}

TEST(QueryCommand, WritesTheSchedulerAsJsonAndAsPrismsAdversary) {
  test::ScratchDirectory dir("query_command_test");
  const std::string dice = std::string(OASIS_SOURCE_DIR) + "/tests/data/prism/two_dice.nm";
  const std::string json = (dir.path() / "s.json").string();
  const std::string adv = (dir.path() / "s.adv").string();
  auto result = run_oasisc("query " + dice + " --prop 'Pmax=? [F \"seven\"]' --scheduler " + json);
  EXPECT_EQ(result.status, 0) << result.output;
  std::ifstream json_in(json);
  const std::string json_text((std::istreambuf_iterator<char>(json_in)), {});
  EXPECT_NE(json_text.find("\"memoryless\""), std::string::npos) << json_text;
  EXPECT_NE(json_text.find("\"property\": \"Pmax=? [F \\\"seven\\\"]\""), std::string::npos)
      << json_text;
  result = run_oasisc("query " + dice + " --prop 'Pmax=? [F \"seven\"]' --scheduler " + adv);
  EXPECT_EQ(result.status, 0) << result.output;
  // The induced chain as a .tra file: every state of the MDP, one distribution each.
  const std::string tra = (dir.path() / "chain.tra").string();
  std::filesystem::copy_file(adv, tra);
  result = run_oasisc("info " + tra);
  EXPECT_EQ(result.status, 0) << result.output;
  EXPECT_NE(result.output.find("169         169"), std::string::npos) << result.output;
  result = run_oasisc("query " + dice + " --prop 'Pmax=? [F \"seven\"]; Pmin=? [F \"two\"]' " +
                      "--scheduler " + adv);
  EXPECT_EQ(result.status, 1) << result.output;
  EXPECT_NE(result.output.find("an .adv file holds one memoryless scheduler"), std::string::npos)
      << result.output;
}

TEST(QueryCommand, ThePrecisionIsANumberAsEveryRealOptionIs) {
  for (const char* bad : {"nan", "inf", "0x1p-20", "1e-6x", "0", "1"}) {
    const auto result = run_oasisc("query " + kDie + " --prop 'P=? [F face=1]' --precision " + bad);
    EXPECT_EQ(result.status, 2) << bad << ": " << result.output;
    EXPECT_NE(result.output.find("is not a number in [1e-15, 0.5]"), std::string::npos)
        << result.output;
  }
}

TEST(QueryCommand, WithoutAPropertyIsBadUsage) {
  const auto result = run_oasisc("query " + kDie);
  EXPECT_EQ(result.status, 2) << result.output;
  EXPECT_NE(result.output.find("--prop"), std::string::npos) << result.output;
}

}  // namespace
}  // namespace oasis
