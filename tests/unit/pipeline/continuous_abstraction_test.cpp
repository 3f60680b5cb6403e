// A continuous context abstracted end to end: grid, finite MDP, bisimulation, policy.

#include "pipeline/continuous_abstraction.hpp"

#include <algorithm>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "../../support/spec_models.hpp"
#include "codegen/abstraction_svg.hpp"
#include "codegen/continuous_json.hpp"
#include "frontend/load_spec.hpp"
#include "pipeline/continuous_catalog.hpp"

namespace oasis {
namespace {

TEST(ContinuousAbstraction, DeterministicLineIsAnExactBisimulationWithTheObviousPolicy) {
  const model::ModelIR ir = test::check_spec_text_ir(test::kDeterministicLineSpec);

  std::string error;
  const auto abstraction = pipeline::abstract_context(ir, 0, {}, error);
  ASSERT_TRUE(abstraction) << error;
  EXPECT_TRUE(abstraction->exact());
  EXPECT_EQ(abstraction->num_cells(), 10U);
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
  const model::ModelIR ir = test::shipped_go1_spec();
  std::string error;
  pipeline::ContinuousOptions options;
  options.target.epsilon = 0.3;  // coarse, to keep the test quick
  const auto abstraction = pipeline::abstract_context(ir, 1, options, error);
  ASSERT_TRUE(abstraction) << error;
  EXPECT_EQ(abstraction->axis_names, (std::vector<std::string>{"x2", "y2"}));
  EXPECT_TRUE(abstraction->met);
  EXPECT_FALSE(abstraction->exact());
  EXPECT_LE(to_double(abstraction->epsilon), 0.3);
  ASSERT_EQ(abstraction->cell_block.size(), abstraction->num_cells());
  ASSERT_EQ(abstraction->policy.size(), abstraction->num_blocks);
  // The best place is in reach of human 2: the reward region's cells have the top value.
  const double best = *std::max_element(abstraction->value.begin(), abstraction->value.end());
  const double in_reach[2] = {0.55, 0.0};
  const auto x = abstraction->cells.locate(0, in_reach[0]);
  const auto y = abstraction->cells.locate(1, in_reach[1]);
  ASSERT_TRUE(x && y);
  const std::uint32_t index[2] = {*x, *y};
  const std::uint32_t block = abstraction->cell_block[abstraction->cells.cell_of(index)];
  EXPECT_EQ(abstraction->block_reward[block], 1.0);
  EXPECT_NEAR(abstraction->value[block], best, 0.2 * best);
}

TEST(ContinuousCatalog, JsonFollowsTheContract) {
  const model::ModelIR ir = test::check_spec_text_ir(test::kDeterministicLineSpec);
  std::string error;
  const auto catalog = pipeline::build_continuous_catalog(ir, 7, {}, error);
  ASSERT_TRUE(catalog) << error;
  const nlohmann::json json =
      nlohmann::json::parse(codegen::continuous_catalog_json(*catalog, true));
  EXPECT_EQ(json["name"], "line");
  EXPECT_EQ(json["variables"], nlohmann::json({"x"}));
  EXPECT_EQ(json["actions"], nlohmann::json({"left", "right"}));
  EXPECT_EQ(json["switching"], nlohmann::json({{1.0}}));
  ASSERT_EQ(json["abstractions"].size(), 1U);
  const nlohmann::json& abstraction = json["abstractions"][0];
  EXPECT_EQ(abstraction["context"], "at_goal");
  EXPECT_EQ(abstraction["relevant_variables"], nlohmann::json({"x"}));
  EXPECT_EQ(abstraction["epsilon"], 0.0);
  EXPECT_EQ(abstraction["exact"], true);
  EXPECT_EQ(abstraction["num_blocks"], 11);
  ASSERT_EQ(abstraction["cells"].size(), 10U);
  // Cell 3 is 3 <= x <= 4: A = [[1], [-1]], b = [4, -3].
  const nlohmann::json& cell = abstraction["cells"][3];
  EXPECT_EQ(cell["A"], nlohmann::json({{1}, {-1}}));
  EXPECT_EQ(cell["b"], nlohmann::json({4.0, -3.0}));
  const int block = cell["block"];
  EXPECT_EQ(abstraction["blocks"][block]["reward"], 1.0);
  // Every `next` row is a distribution over blocks.
  for (const auto& entry : abstraction["blocks"]) {
    ASSERT_TRUE(entry.contains("next"));
    for (const auto& [action, row] : entry["next"].items()) {
      double total = 0;
      for (const auto& pair : row) {
        EXPECT_LT(pair[0].get<int>(), 11);
        total += pair[1].get<double>();
      }
      EXPECT_NEAR(total, 1.0, 1e-12) << action;
    }
  }
  EXPECT_FALSE(nlohmann::json::parse(codegen::continuous_catalog_json(
      *catalog, false))["abstractions"][0]["blocks"][0]
                   .contains("next"));
}

TEST(ContinuousCatalog, SvgShowsTheCellsAndTheCaption) {
  const model::ModelIR ir = test::check_spec_text_ir(test::kDeterministicLineSpec);
  std::string error;
  const auto catalog = pipeline::build_continuous_catalog(ir, 7, {}, error);
  ASSERT_TRUE(catalog) << error;
  const std::string svg = codegen::abstraction_svg(*catalog, 0);
  EXPECT_EQ(svg.rfind("<svg", 0), 0U);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  std::size_t rects = 0;
  for (std::size_t at = svg.find("<rect"); at != std::string::npos; at = svg.find("<rect", at + 1))
    ++rects;
  EXPECT_EQ(rects, 10U + 2U);  // ten cells and two legend swatches
  EXPECT_NE(svg.find("line / at_goal: attends to x<"), std::string::npos) << svg;
  EXPECT_NE(svg.find("epsilon 0 (exact bisimulation); 10 cells, 11 blocks"), std::string::npos)
      << svg;
  EXPECT_NE(svg.find("stroke=\"black\""), std::string::npos);  // the reward's outline
}

}  // namespace
}  // namespace oasis
