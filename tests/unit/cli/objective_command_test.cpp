// `oasisc compile` and `oasisc info` on a continuous model with an objective (docs/guarantees.md),
// run as a user runs them: the controller file and its summary, the catalog options refused,
// a map that cannot be enclosed refused at its expression, and rows past the memory budget
// refused at the grid before they are built.

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "../../support/run_oasisc.hpp"
#include "../../support/scratch_directory.hpp"

namespace oasis {
namespace {

std::string spec_text(const std::string& equation) {
  return "mdp swing {\n"
         "  continuous x : [-2 .. 2];\n"
         "  continuous v : [-2 .. 2];\n"
         "  input u in [-1 .. 1] step 1;\n"
         "  actions push;\n"
         "  disturbance x ~ gaussian(0, 0.2);\n"
         "  disturbance v ~ gaussian(0, 0.2);\n"
         "  dynamics [push] { x' = x + 0.1 * v; " +
         equation +
         " }\n"
         "  region home = x >= -0.5 & x <= 0.5 & v >= -0.5 & v <= 0.5;\n"
         "  objective reach home steps 10;\n"
         "  grid x : 8, v : 8;\n"
         "}\n";
}

std::filesystem::path write_spec(const test::ScratchDirectory& dir, const std::string& text) {
  const std::filesystem::path path = dir.path() / "swing.oasis";
  std::ofstream(path) << text;
  return path;
}

TEST(ObjectiveCommand, CompileWritesTheControllerAndSummarisesItsBounds) {
  const test::ScratchDirectory dir("objective_cli");
  const auto spec = write_spec(dir, spec_text("v' = v + 0.1 * (sin(x) - v) + 0.2 * u;"));
  const auto out = dir.path() / "out";
  const test::CommandResult result =
      test::run_oasisc("compile " + spec.string() + " -o " + out.string());
  ASSERT_EQ(result.status, 0) << result.output;
  EXPECT_NE(result.output.find("objective: 64 cells x 3 actions"), std::string::npos)
      << result.output;
  EXPECT_NE(result.output.find("bounds: lower mean"), std::string::npos) << result.output;
  EXPECT_TRUE(std::filesystem::exists(out / "swing.controller.json"));
  const test::CommandResult info = test::run_oasisc("info " + spec.string());
  ASSERT_EQ(info.status, 0) << info.output;
  EXPECT_NE(info.output.find("objective: reach-avoid, 10 steps"), std::string::npos) << info.output;
  EXPECT_NE(info.output.find("inputs: u (3 values); finite actions: 3"), std::string::npos)
      << info.output;
}

TEST(ObjectiveCommand, CatalogOptionsAreRefusedNotIgnored) {
  const test::ScratchDirectory dir("objective_cli");
  const auto spec = write_spec(dir, spec_text("v' = v + 0.2 * u;"));
  for (const std::string option : {"--epsilon 0.1", "--no-attention", "--format bin"}) {
    const test::CommandResult result = test::run_oasisc("compile " + spec.string() + " -o " +
                                                        (dir.path() / "o").string() + " " + option);
    EXPECT_EQ(result.status, 1) << option << ": " << result.output;
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "o")) << option;
  }
}

TEST(ObjectiveCommand, AMapThatCannotBeEnclosedIsALocatedError) {
  const test::ScratchDirectory dir("objective_cli");
  const auto spec = write_spec(dir, spec_text("v' = v + 0.1 / x;"));
  const test::CommandResult result = test::run_oasisc("check " + spec.string());
  EXPECT_EQ(result.status, 1) << result.output;
  EXPECT_NE(result.output.find("swing.oasis:8:48: error: the divisor can be 0 here"),
            std::string::npos)
      << result.output;
  EXPECT_NE(result.output.find("the divisor can be 0 here"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("^"), std::string::npos) << result.output;
}

TEST(ObjectiveCommand, RowsPastTheMemoryBudgetAreRefusedAtTheGrid) {
  const test::ScratchDirectory dir("objective_cli");
  std::string text = spec_text("v' = v + 0.2 * u;");
  text.replace(text.find("grid x : 8, v : 8;"), 18, "grid x : 2000, v : 2000;");
  const auto spec = write_spec(dir, text);
  const test::CommandResult result = test::run_oasisc(
      "compile " + spec.string() + " -o " + (dir.path() / "o").string() + " --memory-budget 64M");
  EXPECT_EQ(result.status, 1) << result.output;
  EXPECT_NE(result.output.find("swing.oasis:11:3: error: the interval MDP would take about"),
            std::string::npos)
      << result.output;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "o"));
}

}  // namespace
}  // namespace oasis
