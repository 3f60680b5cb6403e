// The continuous target's one rule: the flag, else the spec's setting, else the default; a
// budget given by either is that of both paths.

#include "pipeline/continuous_options.hpp"

#include <gtest/gtest.h>

namespace oasis {
namespace {

model::ModelIR spec_with(std::optional<Rational> epsilon, std::optional<std::uint64_t> max_cells) {
  model::ModelIR spec;
  spec.epsilon = epsilon;
  spec.max_cells = max_cells;
  return spec;
}

TEST(ContinuousTarget, NothingGivenTakesTheDefaults) {
  const pipeline::ContinuousTarget target = pipeline::continuous_target(spec_with({}, {}), {});
  EXPECT_EQ(target.epsilon, pipeline::kDefaultEpsilon);
  EXPECT_EQ(target.grid_cells, pipeline::kDefaultGridCells);
  EXPECT_EQ(target.polytope_cells, pipeline::kDefaultPolytopeCells);
  // A default-made target (what a test or a library user gets) is the same.
  const pipeline::ContinuousTarget made;
  EXPECT_EQ(made.epsilon, target.epsilon);
  EXPECT_EQ(made.grid_cells, target.grid_cells);
  EXPECT_EQ(made.polytope_cells, target.polytope_cells);
}

TEST(ContinuousTarget, TheSpecWinsOverTheDefaults) {
  const pipeline::ContinuousTarget target =
      pipeline::continuous_target(spec_with(Rational(1, 4), 500), {});
  EXPECT_DOUBLE_EQ(target.epsilon, 0.25);
  EXPECT_EQ(target.grid_cells, 500U);
  EXPECT_EQ(target.polytope_cells, 500U);
}

TEST(ContinuousTarget, TheFlagsWinOverTheSpec) {
  const pipeline::ContinuousTarget target = pipeline::continuous_target(
      spec_with(Rational(1, 4), 500), {.epsilon = 0.05, .max_cells = 70});
  EXPECT_EQ(target.epsilon, 0.05);
  EXPECT_EQ(target.grid_cells, 70U);
  EXPECT_EQ(target.polytope_cells, 70U);
}

TEST(ContinuousTarget, EachSettingChoosesOnItsOwn) {
  // The flag gives the bound only, the spec the budget only.
  const pipeline::ContinuousTarget target =
      pipeline::continuous_target(spec_with({}, 900), {.epsilon = 0.2, .max_cells = {}});
  EXPECT_EQ(target.epsilon, 0.2);
  EXPECT_EQ(target.grid_cells, 900U);
  EXPECT_EQ(target.polytope_cells, 900U);
  // The spec gives the bound only, the flag the budget only.
  const pipeline::ContinuousTarget other =
      pipeline::continuous_target(spec_with(Rational(3, 10), {}), {.epsilon = {}, .max_cells = 40});
  EXPECT_DOUBLE_EQ(other.epsilon, 0.3);
  EXPECT_EQ(other.grid_cells, 40U);
  EXPECT_EQ(other.polytope_cells, 40U);
}

}  // namespace
}  // namespace oasis
