// The polytope path's rows kept as tree walks (geom/polytope_walk_rows.hpp) against the same
// rows materialised: the same edge count, every expectation equal to the sum over the
// materialised row up to the stated rounding, and the materialised rows equal to those of the
// general path (one exact volume per target cell, successor_row without the walk's
// shortcuts). Then a context solved both ways (pipeline/product_form.hpp): the same blocks
// and policy, values within the solvers' tolerance.

#include "geom/polytope_walk_rows.hpp"

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../../support/random_mdp.hpp"
#include "../../support/solved_both_ways.hpp"
#include "../../support/spec_models.hpp"
#include "geom/polytope_error_bound.hpp"
#include "geom/polytope_geometry.hpp"
#include "geom/polytope_partition.hpp"
#include "geom/polytope_rows.hpp"
#include "geom/relevance.hpp"
#include "pipeline/continuous_abstraction.hpp"

namespace oasis {
namespace {

model::ModelIR triangle() {
  return test::load_spec_ir(std::string(OASIS_SOURCE_DIR) + "/tests/data/triangle_reward.oasis");
}

struct Walked {
  geom::PolytopeGeometry geometry;
  geom::PolytopePartition partition;
};

Walked walked(const model::ModelIR& ir, std::size_t context, double epsilon) {
  std::string error;
  const geom::Relevance relevance = geom::analyse_relevance(ir, context);
  auto geometry = geom::polytope_geometry(ir, context, relevance, error);
  EXPECT_TRUE(geometry) << error;
  auto partition = geom::partition_polytopes(
      *geometry, {.epsilon = Rational(epsilon), .max_cells = 5000}, error);
  EXPECT_TRUE(partition) << error;
  return {std::move(*geometry), std::move(*partition)};
}

TEST(PolytopeWalkRows, ExpectationsMatchTheMaterialisedRowsAndThePolygonWalk) {
  const model::ModelIR ir = triangle();
  for (std::size_t context = 0; context < ir.contexts.size(); ++context) {
    const Walked w = walked(ir, context, 0.2);
    // The partition's own bound is the bound over its final cells (the pipeline reads it).
    EXPECT_EQ(w.partition.epsilon, geom::partition_error_bound(w.geometry, w.partition.tree));
    const geom::PolytopeWalkRows rows(w.geometry, w.partition);
    const model::ExplicitModel mdp = rows.materialise("c", ir.actions, ir.objective);
    test::expect_same_expectations(rows, mdp);
    EXPECT_LT(rows.num_entries(), rows.num_edges());  // some subtree is taken whole
    const model::TransitionMatrix& matrix = *mdp.contexts[0].transitions;
    const geom::BspTree& tree = w.partition.tree;
    for (model::StateIndex s = 0; s < tree.num_cells(); ++s) {
      for (model::ActionIndex a = 0; a < rows.num_actions(); ++a) {
        // The exact row is the one the polygon walk finds, target by target.
        const auto reference = geom::successor_row(w.geometry, tree, w.geometry.actions[a],
                                                   tree.cells()[s].representative);
        ASSERT_EQ(reference.size(), matrix.edges_end(s, a) - matrix.edges_begin(s, a));
        auto e = matrix.edges_begin(s, a);
        for (const auto& [target, p] : reference) {
          EXPECT_EQ(matrix.edge_target[e], target);
          EXPECT_EQ(mdp.values[matrix.edge_probability[e]], p);
          ++e;
        }
      }
    }
  }
}

TEST(PolytopeWalkRows, TreeWalksSolveLikeTheMaterialisedRows) {
  pipeline::ContinuousOptions options;
  options.target.epsilon = 0.15;
  test::expect_solved_alike(triangle(), 0, options);
  test::expect_solved_alike(triangle(), 1, options);
}

}  // namespace
}  // namespace oasis
