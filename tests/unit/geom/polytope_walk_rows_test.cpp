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
#include "../../support/spec_models.hpp"
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

TEST(PolytopeWalkRows, ExpectationsMatchTheMaterialisedRowsAndTheGeneralPath) {
  const model::ModelIR ir = triangle();
  for (std::size_t context = 0; context < ir.contexts.size(); ++context) {
    const Walked w = walked(ir, context, 0.2);
    const geom::PolytopeWalkRows rows(w.geometry, w.partition);
    const model::ExplicitModel mdp = rows.materialise("c", ir.actions, ir.objective);
    const model::TransitionMatrix& matrix = *mdp.contexts[0].transitions;
    ASSERT_EQ(rows.num_states(), mdp.num_states());
    EXPECT_EQ(rows.num_edges(), matrix.num_edges());
    EXPECT_LT(rows.num_entries(), rows.num_edges());  // some subtree is taken whole
    EXPECT_GT(rows.rounding_depth(), 0U);
    EXPECT_GT(rows.smallest_term(), 0.0);

    test::TestRandom random(11);
    std::vector<double> x(rows.num_states());
    for (double& v : x)
      v = static_cast<double>(random.below(1000)) / 7.0;
    rows.prepare(x.data());
    const double u = std::ldexp(1.0, -53);
    const geom::BspTree& tree = w.partition.tree;
    for (model::StateIndex s = 0; s < rows.num_states(); ++s) {
      for (model::ActionIndex a = 0; a < rows.num_actions(); ++a) {
        double sum = 0;
        for (auto e = matrix.edges_begin(s, a); e < matrix.edges_end(s, a); ++e)
          sum += to_double(mdp.values[matrix.edge_probability[e]]) * x[matrix.edge_target[e]];
        const double walk = rows.expectation(s, a, x.data());
        const double depth =
            rows.rounding_depth() + (matrix.edges_end(s, a) - matrix.edges_begin(s, a));
        ASSERT_NEAR(walk, sum, 2 * depth * u * sum + 1e-300) << "state " << s << ", action " << a;
        if (s == tree.num_cells()) continue;  // outside
        // The exact row is the one the general path finds, target by target.
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
  const model::ModelIR ir = triangle();
  std::string error;
  pipeline::ContinuousOptions options;
  options.target.epsilon = 0.15;
  options.grid_rows = pipeline::GridRows::kMaterialised;
  const auto materialised = pipeline::abstract_context(ir, 0, options, error);
  ASSERT_TRUE(materialised) << error;
  options.grid_rows = pipeline::GridRows::kProduct;
  const auto walks = pipeline::abstract_context(ir, 0, options, error);
  ASSERT_TRUE(walks) << error;

  EXPECT_EQ(materialised->num_blocks, materialised->num_cells() + 1);
  EXPECT_EQ(walks->num_blocks, materialised->num_blocks);
  EXPECT_EQ(walks->cell_block, materialised->cell_block);
  EXPECT_EQ(walks->outside_block, materialised->outside_block);
  EXPECT_EQ(walks->block_reward, materialised->block_reward);
  EXPECT_EQ(walks->finite_edges, materialised->finite_edges);
  EXPECT_EQ(walks->epsilon, materialised->epsilon);
  ASSERT_EQ(walks->value.size(), materialised->value.size());
  for (std::size_t z = 0; z < walks->value.size(); ++z)
    EXPECT_NEAR(walks->value[z], materialised->value[z], options.policy.tolerance) << z;
  EXPECT_EQ(walks->policy, materialised->policy);
  EXPECT_EQ(walks->quotient.contexts[0].transitions->num_edges(), 0U);
  options.keep_rows = true;
  const auto with_rows = pipeline::abstract_context(ir, 0, options, error);
  ASSERT_TRUE(with_rows) << error;
  const model::TransitionMatrix& kept = *with_rows->quotient.contexts[0].transitions;
  const model::TransitionMatrix& reference = *materialised->quotient.contexts[0].transitions;
  EXPECT_EQ(kept.edge_target, reference.edge_target);
  ASSERT_EQ(kept.num_edges(), reference.num_edges());
  for (std::size_t e = 0; e < kept.num_edges(); ++e)
    ASSERT_EQ(with_rows->quotient.values[kept.edge_probability[e]],
              materialised->quotient.values[reference.edge_probability[e]]);
}

}  // namespace
}  // namespace oasis
