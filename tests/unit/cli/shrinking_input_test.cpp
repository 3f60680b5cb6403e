// An input cut short while oasisc reads it (issue 37, item 8) was a SIGBUS (status 135). Now it
// is "PATH: error: the file changed size while being read", status 1, and nothing written. The
// test hook OASIS_TEST_SHRINK_INPUT cuts the file once the reader has mapped it and before it
// reads (support/mapped_file.hpp), so the cut always lands at the same point.

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../../support/run_oasisc.hpp"
#include "../../support/scratch_files.hpp"

namespace {

namespace fs = std::filesystem;
using oasis::test::CommandResult;
using oasis::test::output_has;
using oasis::test::run_oasisc;

// A chain of `states` states: about 12 bytes a state, many pages for a few thousand.
std::string chain_aut(int states) {
  std::string text = "des (0," + std::to_string(states) + "," + std::to_string(states) + ")\n";
  for (int s = 0; s + 1 < states; ++s)
    text += "(" + std::to_string(s) + ",\"a\"," + std::to_string(s + 1) + ")\n";
  text +=
      "(" + std::to_string(states - 1) + ",\"a|reward(1)\"," + std::to_string(states - 1) + ")\n";
  return text;
}

class ShrinkingInput : public oasis::test::ScratchFilesTest {
 protected:
  ShrinkingInput() : ScratchFilesTest("oasis_shrinking_input_test") {}
  ~ShrinkingInput() override { ::unsetenv("OASIS_TEST_SHRINK_INPUT"); }

  // Runs oasisc with the input cut to `bytes` once it is mapped.
  static CommandResult run_cut(const std::string& arguments, const char* bytes) {
    ::setenv("OASIS_TEST_SHRINK_INPUT", bytes, 1);
    CommandResult result = run_oasisc(arguments);
    ::unsetenv("OASIS_TEST_SHRINK_INPUT");
    return result;
  }
};

TEST_F(ShrinkingInput, QuotientOfAnAutCutToNothingIsAnErrorAndWritesNothing) {
  const fs::path model = write("model.aut", chain_aut(20000));
  const fs::path out = scratch_.path() / "partition.json";
  const CommandResult result =
      run_cut("quotient " + model.string() + " --format json -o " + out.string(), "0");
  EXPECT_EQ(result.status, 1) << result.output;
  EXPECT_TRUE(
      output_has(result, model.string() + ": error: the file changed size while being read"))
      << result.output;
  EXPECT_EQ(entries(), std::vector<std::string>{"model.aut"});
}

// Cut after its first page: the reader gets that far, then meets the missing rest.
TEST_F(ShrinkingInput, QuotientOfAnAutCutMidwayIsAnError) {
  const fs::path model = write("model.aut", chain_aut(20000));
  const CommandResult result = run_cut(
      "quotient " + model.string() + " --format aut -o " + (scratch_.path() / "q.aut").string(),
      "4096");
  EXPECT_EQ(result.status, 1) << result.output;
  EXPECT_TRUE(output_has(result, "model.aut: error: the file changed size while being read"))
      << result.output;
  EXPECT_EQ(entries(), std::vector<std::string>{"model.aut"});
}

TEST_F(ShrinkingInput, CompileOfASpecCutToNothingIsAnErrorAndWritesNothing) {
  std::ifstream shipped(std::string(OASIS_SOURCE_DIR) + "/specs/discrete_tracking.oasis");
  const std::string text{std::istreambuf_iterator<char>(shipped), {}};
  ASSERT_FALSE(text.empty());
  const fs::path path = write("m.oasis", "// " + std::string(10000, '-') + "\n" + text);
  const fs::path out = scratch_.path() / "out";
  const CommandResult result = run_cut("compile " + path.string() + " -o " + out.string(), "0");
  EXPECT_EQ(result.status, 1) << result.output;
  EXPECT_TRUE(output_has(result, "m.oasis: error: the file changed size while being read"))
      << result.output;
  EXPECT_EQ(entries(), std::vector<std::string>{"m.oasis"});
}

// Without the hook the same inputs compile: the hook, not the inputs, made the errors above.
TEST_F(ShrinkingInput, TheSameInputsUncutAreRead) {
  const fs::path model = write("model.aut", chain_aut(20000));
  const CommandResult result = run_oasisc("quotient " + model.string());
  EXPECT_EQ(result.status, 0) << result.output;
}

}  // namespace
