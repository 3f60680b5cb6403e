#pragma once
// Compact rows against materialised ones, for the tests of both compact forms: their
// expectations, and a continuous context solved both ways (pipeline/product_form.hpp;
// --grid-rows materialised against product): the same blocks, rewards, edge count and
// policy, values within the solvers' tolerance, no rows kept unless asked for, and with
// --with-transitions the same exact quotient rows.

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "pipeline/continuous_abstraction.hpp"
#include "random_mdp.hpp"

namespace oasis::test {

// Every expectation of compact rows (geom/grid_product_rows.hpp, geom/polytope_walk_rows.hpp)
// against the materialised rows `mdp`, for a seeded non-negative x, and the same rewards:
// both sums are within (1 + u)^depth - 1 of the exact one, relative (non-negative terms).
template <class Rows>
void expect_same_expectations(const Rows& rows, const model::ExplicitModel& mdp) {
  const model::TransitionMatrix& matrix = *mdp.contexts[0].transitions;
  ASSERT_EQ(rows.num_states(), mdp.num_states());
  EXPECT_EQ(rows.num_edges(), matrix.num_edges());
  EXPECT_GT(rows.rounding_depth(), 0U);
  EXPECT_GT(rows.smallest_term(), 0.0);
  TestRandom random(7);
  std::vector<double> x(rows.num_states());
  for (double& v : x)
    v = static_cast<double>(random.below(1000)) / 7.0;
  if constexpr (requires { rows.prepare(x.data()); }) rows.prepare(x.data());
  const double u = std::ldexp(1.0, -53);
  for (model::StateIndex s = 0; s < rows.num_states(); ++s) {
    EXPECT_EQ(rows.values()[rows.state_reward(s)], mdp.values[mdp.contexts[0].rewards.state[s]]);
    for (model::ActionIndex a = 0; a < rows.num_actions(); ++a) {
      double sum = 0;
      for (auto e = matrix.edges_begin(s, a); e < matrix.edges_end(s, a); ++e)
        sum += to_double(mdp.values[matrix.edge_probability[e]]) * x[matrix.edge_target[e]];
      const double compact = rows.expectation(s, a, x.data());
      const double depth =
          rows.rounding_depth() + (matrix.edges_end(s, a) - matrix.edges_begin(s, a));
      ASSERT_NEAR(compact, sum, 2 * depth * u * sum + 1e-300) << "state " << s << ", action " << a;
    }
  }
}

inline void expect_solved_alike(const model::ModelIR& ir, std::size_t context,
                                pipeline::ContinuousOptions options) {
  std::string error;
  options.grid_rows = pipeline::GridRows::kMaterialised;
  const auto materialised = pipeline::abstract_context(ir, context, options, error);
  ASSERT_TRUE(materialised) << error;
  options.grid_rows = pipeline::GridRows::kProduct;
  const auto compact = pipeline::abstract_context(ir, context, options, error);
  ASSERT_TRUE(compact) << error;

  // The exact refinement finds no two cells bisimilar, and the proof says as much.
  EXPECT_EQ(materialised->num_blocks, materialised->num_cells() + 1);
  EXPECT_EQ(compact->num_blocks, materialised->num_blocks);
  EXPECT_EQ(compact->cell_block, materialised->cell_block);
  EXPECT_EQ(compact->outside_block, materialised->outside_block);
  EXPECT_EQ(compact->block_reward, materialised->block_reward);
  EXPECT_EQ(compact->finite_edges, materialised->finite_edges);
  EXPECT_EQ(compact->epsilon, materialised->epsilon);
  ASSERT_EQ(compact->value.size(), materialised->value.size());
  // Each is within tolerance/2 of the optimum (policy/objective.hpp).
  for (std::size_t z = 0; z < compact->value.size(); ++z)
    EXPECT_NEAR(compact->value[z], materialised->value[z], options.policy.tolerance) << z;
  EXPECT_EQ(compact->policy, materialised->policy);
  // Without --with-transitions the compact form keeps no rows; with it, the same rows.
  EXPECT_EQ(compact->quotient.contexts[0].transitions->num_edges(), 0U);
  options.keep_rows = true;
  const auto with_rows = pipeline::abstract_context(ir, context, options, error);
  ASSERT_TRUE(with_rows) << error;
  const model::TransitionMatrix& kept = *with_rows->quotient.contexts[0].transitions;
  const model::TransitionMatrix& reference = *materialised->quotient.contexts[0].transitions;
  EXPECT_EQ(kept.edge_target, reference.edge_target);
  ASSERT_EQ(kept.num_edges(), reference.num_edges());
  for (std::size_t e = 0; e < kept.num_edges(); ++e)
    ASSERT_EQ(with_rows->quotient.values[kept.edge_probability[e]],
              materialised->quotient.values[reference.edge_probability[e]]);
}

}  // namespace oasis::test
