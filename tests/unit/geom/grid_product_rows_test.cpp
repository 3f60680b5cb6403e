// The grid's rows in product form (geom/grid_product_rows.hpp) against the materialised finite
// MDP (geom/grid_mdp.hpp): the same edge count, and every expectation equal to the sum over
// the materialised row up to rounding; in 1, 2 and 4 dimensions, uniform and Gaussian. Then a
// context solved both ways (pipeline/product_form.hpp): the same blocks and policy, values
// within the solvers' tolerance.

#include "geom/grid_product_rows.hpp"

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../../support/random_mdp.hpp"
#include "../../support/spec_models.hpp"
#include "bisim/refinement.hpp"
#include "geom/grid_geometry.hpp"
#include "geom/grid_mdp.hpp"
#include "geom/grid_refinement.hpp"
#include "geom/relevance.hpp"
#include "pipeline/continuous_abstraction.hpp"

namespace oasis {
namespace {

// Every expectation of `rows` against the materialised rows, for a seeded non-negative x.
void expect_same_rows(const model::ModelIR& ir, std::size_t context, bool attention, double epsilon,
                      std::size_t max_cells) {
  std::string error;
  const geom::Relevance relevance =
      attention ? geom::analyse_relevance(ir, context) : geom::full_state(ir);
  const auto geometry = geom::grid_geometry(ir, context, relevance, error);
  ASSERT_TRUE(geometry) << error;
  const auto partition = geom::partition_grid(*geometry, {epsilon, max_cells}, error);
  ASSERT_TRUE(partition) << error;
  const geom::ProductRows rows(*geometry, partition->grid,
                               static_cast<std::uint32_t>(ir.actions.size()));
  const model::ExplicitModel mdp =
      geom::grid_finite_mdp(*geometry, partition->grid, ir.actions, ir.objective);
  const model::TransitionMatrix& matrix = *mdp.contexts[0].transitions;
  ASSERT_EQ(rows.num_states(), mdp.num_states());
  EXPECT_EQ(rows.num_edges(), matrix.num_edges());
  EXPECT_GT(rows.rounding_depth(), 0U);
  EXPECT_GT(rows.smallest_term(), 0.0);

  test::TestRandom random(7);
  std::vector<double> x(rows.num_states());
  for (double& v : x)
    v = static_cast<double>(random.below(1000)) / 7.0;
  const double u = std::ldexp(1.0, -53);
  for (model::StateIndex s = 0; s < rows.num_states(); ++s) {
    EXPECT_EQ(rows.values()[rows.state_reward(s)], mdp.values[mdp.contexts[0].rewards.state[s]]);
    for (model::ActionIndex a = 0; a < rows.num_actions(); ++a) {
      double sum = 0;
      for (auto e = matrix.edges_begin(s, a); e < matrix.edges_end(s, a); ++e)
        sum += to_double(mdp.values[matrix.edge_probability[e]]) * x[matrix.edge_target[e]];
      const double product = rows.expectation(s, a, x.data());
      // Both are within (1 + u)^depth - 1 of the exact sum, relative (non-negative terms).
      const double depth =
          rows.rounding_depth() + (matrix.edges_end(s, a) - matrix.edges_begin(s, a));
      ASSERT_NEAR(product, sum, 2 * depth * u * sum + 1e-300) << "state " << s << ", action " << a;
    }
  }
}

TEST(GridProductRows, Go1InTwoDimensionsMatchesTheMaterialisedRows) {
  expect_same_rows(test::shipped_go1_spec(), 0, true, 0.3, 100000);
}

TEST(GridProductRows, Go1InFourDimensionsMatchesTheMaterialisedRows) {
  expect_same_rows(test::shipped_go1_spec(), 1, false, 0.5, 3000);
}

TEST(GridProductRows, GaussianLineMatchesTheMaterialisedRows) {
  expect_same_rows(
      test::load_spec_ir(std::string(OASIS_SOURCE_DIR) + "/tests/data/gaussian_line.oasis"), 0,
      true, 0.1, 100000);
}

TEST(GridProductRows, ProductFormSolvesTheGo1LikeTheMaterialisedRows) {
  const model::ModelIR ir = test::shipped_go1_spec();
  std::string error;
  pipeline::ContinuousOptions options;
  options.target.epsilon = 0.25;
  options.grid_rows = pipeline::GridRows::kMaterialised;
  const auto materialised = pipeline::abstract_context(ir, 0, options, error);
  ASSERT_TRUE(materialised) << error;
  options.grid_rows = pipeline::GridRows::kProduct;
  const auto product = pipeline::abstract_context(ir, 0, options, error);
  ASSERT_TRUE(product) << error;

  // The exact refinement finds no two cells bisimilar, and the proof says as much.
  EXPECT_EQ(materialised->num_blocks, materialised->num_cells() + 1);
  EXPECT_EQ(product->num_blocks, materialised->num_blocks);
  EXPECT_EQ(product->cell_block, materialised->cell_block);
  EXPECT_EQ(product->outside_block, materialised->outside_block);
  EXPECT_EQ(product->block_reward, materialised->block_reward);
  EXPECT_EQ(product->finite_edges, materialised->finite_edges);
  ASSERT_EQ(product->value.size(), materialised->value.size());
  // Each is within tolerance/2 of the optimum (policy/objective.hpp).
  for (std::size_t z = 0; z < product->value.size(); ++z)
    EXPECT_NEAR(product->value[z], materialised->value[z], options.policy.tolerance) << z;
  EXPECT_EQ(product->policy, materialised->policy);
  // Without --with-transitions the product form keeps no rows; with it, the same rows.
  EXPECT_EQ(product->quotient.contexts[0].transitions->num_edges(), 0U);
  options.keep_rows = true;
  const auto with_rows = pipeline::abstract_context(ir, 0, options, error);
  ASSERT_TRUE(with_rows) << error;
  const model::TransitionMatrix& kept = *with_rows->quotient.contexts[0].transitions;
  const model::TransitionMatrix& reference = *materialised->quotient.contexts[0].transitions;
  EXPECT_EQ(kept.edge_target, reference.edge_target);
  EXPECT_EQ(kept.num_edges(), reference.num_edges());
}

}  // namespace
}  // namespace oasis
