// A continuous context abstracted end to end: grid, finite MDP, bisimulation, policy.

#include "pipeline/continuous_abstraction.hpp"

#include <algorithm>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "spec/frontend.hpp"

namespace oasis {
namespace {

model::ModelIR load(const std::string& path) {
  SourceManager sources;
  std::ostringstream messages;
  DiagnosticEngine diagnostics(sources, messages);
  auto ir = spec::load_spec(path, sources, diagnostics);
  EXPECT_TRUE(ir) << messages.str();
  return ir ? std::move(*ir) : model::ModelIR{};
}

model::ModelIR checked_text(const std::string& text) {
  SourceManager sources;
  std::ostringstream messages;
  DiagnosticEngine diagnostics(sources, messages);
  auto ir = spec::check_spec_text(sources.add("test.oasis", text), diagnostics);
  EXPECT_TRUE(ir) << messages.str();
  return ir ? std::move(*ir) : model::ModelIR{};
}

TEST(ContinuousAbstraction, DeterministicLineIsAnExactBisimulationWithTheObviousPolicy) {
  const model::ModelIR ir = checked_text(R"(
mdp line {
  continuous x : [0 .. 10];
  actions left, right;
  discount 0.9;
  dynamics [left] { x' = x - 1; }
  dynamics [right] { x' = x + 1; }
  region goal = x >= 3 & x <= 4;
}
catalog { context at_goal { reward goal : 1; } }
)");
  std::string error;
  const auto abstraction = pipeline::abstract_context(ir, 0, {}, error);
  ASSERT_TRUE(abstraction) << error;
  EXPECT_TRUE(abstraction->exact());
  EXPECT_EQ(abstraction->grid.num_cells(), 10U);
  EXPECT_EQ(abstraction->num_blocks, 11U);
  // Left of the goal go right, right of it go left; the goal's own cell cannot stay, and
  // leaving it either way comes back in two steps: both are optimal, the lower index wins.
  const auto action_at = [&](std::size_t cell) {
    return abstraction->policy[abstraction->cell_block[cell]];
  };
  for (std::size_t cell = 0; cell < 3; ++cell)
    EXPECT_EQ(action_at(cell), 1U) << cell;  // right
  for (std::size_t cell = 4; cell < 10; ++cell)
    EXPECT_EQ(action_at(cell), 0U) << cell;  // left
  EXPECT_EQ(abstraction->block_reward[abstraction->cell_block[3]], 1.0);
  EXPECT_EQ(abstraction->block_reward[abstraction->outside_block], 0.0);
  EXPECT_EQ(abstraction->value[abstraction->outside_block], 0.0);
}

TEST(ContinuousAbstraction, Go1ContextAttendsToItsHumanAndMeetsTheTarget) {
  const model::ModelIR ir = load(std::string(OASIS_SOURCE_DIR) + "/specs/go1_treat.oasis");
  std::string error;
  pipeline::ContinuousOptions options;
  options.epsilon = 0.3;  // coarse, to keep the test quick
  const auto abstraction = pipeline::abstract_context(ir, 1, options, error);
  ASSERT_TRUE(abstraction) << error;
  EXPECT_EQ(abstraction->axis_names, (std::vector<std::string>{"x2", "y2"}));
  EXPECT_TRUE(abstraction->met);
  EXPECT_FALSE(abstraction->exact());
  EXPECT_LE(to_double(abstraction->epsilon), 0.3);
  ASSERT_EQ(abstraction->cell_block.size(), abstraction->grid.num_cells());
  ASSERT_EQ(abstraction->policy.size(), abstraction->num_blocks);
  // The best place is in reach of human 2: the reward region's cells have the top value.
  const double best = *std::max_element(abstraction->value.begin(), abstraction->value.end());
  const double in_reach[2] = {0.55, 0.0};
  const auto cell = abstraction->grid.locate(std::span<const double>(in_reach, 2));
  ASSERT_TRUE(cell);
  const std::uint32_t block = abstraction->cell_block[*cell];
  EXPECT_EQ(abstraction->block_reward[block], 1.0);
  EXPECT_NEAR(abstraction->value[block], best, 0.2 * best);
}

}  // namespace
}  // namespace oasis
