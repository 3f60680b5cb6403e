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
#include "../../support/solved_both_ways.hpp"
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
  test::expect_same_expectations(rows, mdp);
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
  pipeline::ContinuousOptions options;
  options.target.epsilon = 0.25;
  test::expect_solved_alike(test::shipped_go1_spec(), 0, options);
}

}  // namespace
}  // namespace oasis
