// Each front-end error is printed once, by every command that loads a model (issue 39: a
// PRISM program with a stray '.' made the lexer report the same character until the error
// limit, which looked like `info` printing the error twice).

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../../support/run_oasisc.hpp"
#include "../../support/scratch_directory.hpp"

namespace {

std::size_t count_of(const std::string& text, const std::string& what) {
  std::size_t count = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
    ++count;
  return count;
}

class ErrorsOnce : public ::testing::Test {
 protected:
  [[nodiscard]] std::string write(const std::string& name, const std::string& text) const {
    const auto path = scratch_.path() / name;
    std::ofstream(path) << text;
    return path.string();
  }

  // Runs every command that loads `file` and expects `error` exactly once in each output.
  void expect_once(const std::string& file, const std::string& error) const {
    const std::string out = (scratch_.path() / "out").string();
    const std::vector<std::string> commands = {
        "info " + file,
        "info --json " + file,
        "check " + file,
        "quotient " + file,
        "compile " + file + " -o " + out,
        "export " + file + " --format aut -o " + out + ".aut",
    };
    for (const std::string& command : commands) {
      const oasis::test::CommandResult result = oasis::test::run_oasisc(command);
      EXPECT_NE(result.status, 0) << command;
      EXPECT_EQ(count_of(result.output, error), 1U) << command << "\n" << result.output;
      EXPECT_EQ(count_of(result.output, ": error:"), 1U) << command << "\n" << result.output;
    }
  }

  oasis::test::ScratchDirectory scratch_{"oasis_errors_once_test"};
};

TEST_F(ErrorsOnce, APrismLexerError) {
  const std::string file = write(
      "dot.pm", "dtmc\nconst double p = 2.;\nmodule m x : [0..1]; [] true -> true; endmodule\n");
  expect_once(file, "dot.pm:2:19: error: unexpected character '.'");
}

TEST_F(ErrorsOnce, AnUnknownCharacterRun) {
  const std::string file =
      write("dollar.pm", "dtmc\nmodule m x : [0..1]; [] true -> true $$ ; endmodule\n");
  expect_once(file, "dollar.pm:2:38: error: unexpected character '$'");
}

TEST_F(ErrorsOnce, AnAutReaderError) {
  const std::string file = write("bad.aut", "des (0,1,2)\n(0,\"a\",1 1/2 1 1/2 3)\n");
  expect_once(file, "bad.aut:2:");
}

TEST_F(ErrorsOnce, ADrnReaderError) {
  const std::string file =
      write("bad.drn", "@type: DTMC\n@nr_states\n1\n@model\nstate 0 init\n\taction 0\n\t\t0 : 2\n");
  expect_once(file, "bad.drn:6:2: error: probabilities of state 0, choice 0 sum to 2");
}

TEST_F(ErrorsOnce, AStormLabelsError) {
  const std::string file = write("storm.tra", "dtmc\n0 0 1\n");
  (void)write("storm.lab", "#DECLARATION\ninit\n#END\n0 init goal\n");
  expect_once(file, "storm.lab:4:8: error: label 'goal'");
}

}  // namespace
