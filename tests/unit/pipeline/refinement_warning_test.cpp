// A refinement that cannot reach its error target within the cell budget says so as soon as
// that is known, before the long stages after the partition (issue 28): the grid path once its
// grid is chosen, the polytope path at half the budget and again when it stops.

#include <string>

#include <gtest/gtest.h>

#include "../../support/run_oasisc.hpp"
#include "../../support/scratch_directory.hpp"

namespace oasis {
namespace {

std::string compile(const test::ScratchDirectory& scratch, const std::string& spec,
                    const std::string& options, int& status) {
  const auto result =
      test::run_oasisc("compile '" + std::string(OASIS_SOURCE_DIR) + "/tests/data/" + spec +
                       "' -o '" + (scratch.path() / "out").string() + "' " + options);
  status = result.status;
  return result.output;
}

TEST(RefinementWarning, TheGridPathWarnsBeforeTheSummary) {
  const test::ScratchDirectory scratch("refine_grid");
  int status = 0;
  const std::string output = compile(scratch, "gaussian_line.oasis",
                                     "--epsilon 0.001 --max-cells 50 --progress never", status);
  EXPECT_EQ(status, 0) << output;
  const std::size_t warning = output.find("warning: context");
  ASSERT_NE(warning, std::string::npos) << output;
  EXPECT_NE(output.find("stops the refinement at 50 cells", warning), std::string::npos) << output;
  EXPECT_NE(output.find("above the target 0.001"), std::string::npos) << output;
  EXPECT_LT(warning, output.find("attends to")) << output;  // before the summary of the run

  const std::string met = compile(scratch, "gaussian_line.oasis", "--progress never", status);
  EXPECT_EQ(status, 0) << met;
  EXPECT_EQ(met.find("warning"), std::string::npos) << met;
}

TEST(RefinementWarning, ThePolytopePathWarnsAtHalfTheBudget) {
  const test::ScratchDirectory scratch("refine_polytope");
  int status = 0;
  const std::string output = compile(scratch, "triangle_reward.oasis",
                                     "--epsilon 0.01 --max-cells 60 --progress never", status);
  EXPECT_EQ(status, 0) << output;
  const std::size_t half = output.find("half the cell budget (30 of 60 cells) is spent");
  ASSERT_NE(half, std::string::npos) << output;
  EXPECT_LT(half, output.find("stops the refinement at 60 cells")) << output;
}

}  // namespace
}  // namespace oasis
