// The gridded abstraction of continuous contexts: the partition, its sound error bound, the
// exact probabilities of the finite MDP, and what the bisimulation engine makes of it.

#include <chrono>
#include <cmath>
#include <iostream>
#include <optional>
#include <random>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "../../support/spec_models.hpp"
#include "bisim/refinement.hpp"
#include "frontend/load_spec.hpp"
#include "geom/grid_geometry.hpp"
#include "geom/grid_mdp.hpp"
#include "geom/grid_refinement.hpp"
#include "geom/relevance.hpp"

namespace oasis {
namespace {

geom::GridGeometry geometry_of(const model::ModelIR& ir, std::size_t context) {
  std::string error;
  auto geometry = geom::grid_geometry(ir, context, geom::analyse_relevance(ir, context), error);
  EXPECT_TRUE(geometry) << error;
  return geometry ? std::move(*geometry) : geom::GridGeometry{};
}

TEST(GeomGrid, Go1ContextMeetsTheTarget) {
  const model::ModelIR ir = test::shipped_go1_spec();
  const geom::GridGeometry geometry = geometry_of(ir, 0);
  ASSERT_EQ(geometry.dimension(), 2U);
  std::string error;
  const auto start = std::chrono::steady_clock::now();
  auto partition = geom::partition_grid(geometry, {.epsilon = 0.1, .max_cells = 100000}, error);
  ASSERT_TRUE(partition) << error;
  EXPECT_TRUE(partition->met);
  EXPECT_LE(to_double(partition->epsilon), 0.1);
  const auto gridded = std::chrono::steady_clock::now();
  const model::ExplicitModel mdp =
      geom::grid_finite_mdp(geometry, partition->grid, ir.actions, ir.objective);
  const auto built = std::chrono::steady_clock::now();
  EXPECT_FALSE(model::find_structural_problem(mdp)) << *model::find_structural_problem(mdp);
  const model::Partition blocks = bisim::coarsest_bisimulation(mdp, 0);
  const auto quotiented = std::chrono::steady_clock::now();
  auto seconds = [](auto a, auto b) { return std::chrono::duration<double>(b - a).count(); };
  std::cout << "cells " << partition->grid.num_cells() << ", epsilon "
            << to_double(partition->epsilon) << ", edges "
            << mdp.contexts[0].transitions->num_edges() << ", blocks " << blocks.num_blocks
            << "; grid " << seconds(start, gridded) << " s, mdp " << seconds(gridded, built)
            << " s, bisimulation " << seconds(built, quotiented) << " s\n";
}

// Deterministic unit shifts of a line with a reward on [3, 4]: the pre-images of the reward's
// and the domain's ends are the integers, so the cells are the ten unit intervals, every
// row is exact (epsilon 0) and goes to the neighbouring cell or outside.
TEST(GeomGrid, DeterministicShiftsGiveTheAnalyticCellsExactly) {
  const model::ModelIR ir = test::check_spec_text_ir(test::kDeterministicLineSpec);
  const geom::GridGeometry geometry = geometry_of(ir, 0);
  std::string error;
  auto partition = geom::partition_grid(geometry, {.epsilon = 0.1, .max_cells = 1000}, error);
  ASSERT_TRUE(partition) << error;
  EXPECT_EQ(partition->epsilon, 0);
  EXPECT_TRUE(partition->met);
  std::vector<Rational> integers;
  for (int k = 0; k <= 10; ++k)
    integers.emplace_back(k);
  EXPECT_EQ(partition->grid.breaks(0), integers);

  const model::ExplicitModel mdp =
      geom::grid_finite_mdp(geometry, partition->grid, ir.actions, ir.objective);
  ASSERT_EQ(mdp.num_states(), 11U);  // ten cells and outside
  const model::TransitionMatrix& matrix = *mdp.contexts[0].transitions;
  const model::StateIndex outside = 10;
  for (model::StateIndex cell = 0; cell < 10; ++cell) {
    for (model::ActionIndex a = 0; a < 2; ++a) {
      ASSERT_EQ(matrix.edges_end(cell, a) - matrix.edges_begin(cell, a), 1U);
      const model::StateIndex target = matrix.edge_target[matrix.edges_begin(cell, a)];
      const int expected = static_cast<int>(cell) + (a == 0 ? -1 : 1);
      EXPECT_EQ(target, expected < 0 || expected > 9 ? outside : expected) << cell << " " << a;
    }
    EXPECT_EQ(mdp.values[mdp.contexts[0].rewards.state[cell]], cell == 3 ? 1 : 0);
  }
  EXPECT_EQ(bisim::coarsest_bisimulation(mdp, 0).num_blocks, 11U);
}

TEST(GeomGrid, PreimagesThatDoNotCloseAreRefused) {
  std::string text = test::kDeterministicLineSpec;
  text.replace(text.find("x' = x - 1;"), 11, "x' = 2 * x;");  // pre-images halve towards 0
  const model::ModelIR ir = test::check_spec_text_ir(text);
  std::string error;
  EXPECT_FALSE(geom::partition_grid(geometry_of(ir, 0), {.epsilon = 0.1, .max_cells = 500}, error));
  EXPECT_NE(error.find("more than 500 cells"), std::string::npos) << error;
}

TEST(GeomGrid, TheCellBudgetWinsOverTheTargetAndSaysSo) {
  const model::ModelIR ir = test::shipped_go1_spec();
  std::string error;
  auto partition =
      geom::partition_grid(geometry_of(ir, 0), {.epsilon = 0.01, .max_cells = 2000}, error);
  ASSERT_TRUE(partition) << error;
  EXPECT_FALSE(partition->met);
  EXPECT_LE(partition->grid.num_cells(), 2000U);
  EXPECT_GT(to_double(partition->epsilon), 0.01);
}

// The Go1 spec's first context on a coarse grid (epsilon 0.3) and its finite MDP.
struct GriddedGo1 {
  model::ModelIR ir = test::shipped_go1_spec();
  geom::GridGeometry geometry = geometry_of(ir, 0);
  std::string error;
  std::optional<geom::GridPartition> partition =
      geom::partition_grid(geometry, {.epsilon = 0.3, .max_cells = 100000}, error);
  model::ExplicitModel mdp =
      partition ? geom::grid_finite_mdp(geometry, partition->grid, ir.actions, ir.objective)
                : model::ExplicitModel{};
};

// The error bound holds for every point of a cell: from points sampled in a cell, the
// successor's frequency in every target (and outside) stays within epsilon of the row, plus
// sampling error.
TEST(GeomGrid, MonteCarloSuccessorsAgreeWithTheRowsWithinEpsilon) {
  const GriddedGo1 go1;
  ASSERT_TRUE(go1.partition);
  const model::ModelIR& ir = go1.ir;
  const geom::GridGeometry& geometry = go1.geometry;
  const geom::Grid& grid = go1.partition->grid;
  const model::TransitionMatrix& matrix = *go1.mdp.contexts[0].transitions;
  const model::ExplicitModel& mdp = go1.mdp;
  const double epsilon = to_double(go1.partition->epsilon);
  std::mt19937_64 random(20261124);
  constexpr int kSamples = 10000;
  const double sampling = 5 * std::sqrt(0.25 / kSamples);  // 5 sigma of any frequency
  std::vector<std::uint32_t> index(2);
  for (int trial = 0; trial < 8; ++trial) {
    const std::size_t cell = random() % grid.num_cells();
    grid.index_of(cell, index);
    for (model::ActionIndex a = 0; a < ir.actions.size(); ++a) {
      const geom::AxisDynamics& step = geometry.actions[a];
      std::vector<double> counts(grid.num_cells() + 1, 0);
      for (int k = 0; k < kSamples; ++k) {
        double x[2];
        for (std::size_t i = 0; i < 2; ++i) {
          const double low = grid.breaks_double(i)[index[i]];
          const double high = grid.breaks_double(i)[index[i] + 1];
          x[i] = std::uniform_real_distribution<double>(low, high)(random);
        }
        double next[2];
        for (std::size_t i = 0; i < 2; ++i) {
          next[i] = to_double(step.offset[i]);
          for (std::size_t j = 0; j < 2; ++j)
            next[i] += to_double(step.matrix[i][j]) * x[j];
          const geom::Interval& w = step.disturbance[i].uniform;
          next[i] +=
              std::uniform_real_distribution<double>(to_double(w.low), to_double(w.high))(random);
        }
        const auto target = grid.locate(std::span<const double>(next, 2));
        counts[target ? *target : grid.num_cells()] += 1;
      }
      std::vector<double> row(grid.num_cells() + 1, 0);
      for (auto e = matrix.edges_begin(static_cast<model::StateIndex>(cell), a);
           e < matrix.edges_end(static_cast<model::StateIndex>(cell), a); ++e)
        row[matrix.edge_target[e]] = to_double(mdp.values[matrix.edge_probability[e]]);
      for (std::size_t t = 0; t < row.size(); ++t) {
        ASSERT_LE(std::abs(counts[t] / kSamples - row[t]), epsilon + sampling)
            << "cell " << cell << ", action " << ir.actions[a] << ", target " << t;
      }
    }
  }
}

// The bound at its worst points: from every vertex of a cell, the exact successor
// distribution (computed here in doubles, apart from the compiler's code) is within epsilon
// of the centre's row in total variation, and the bound is not vacuous: somewhere it is
// nearly reached.
TEST(GeomGrid, VerticesStayWithinTheBoundWhichIsNearlyReached) {
  const GriddedGo1 go1;
  ASSERT_TRUE(go1.partition);
  const model::ModelIR& ir = go1.ir;
  const geom::GridGeometry& geometry = go1.geometry;
  const geom::Grid& grid = go1.partition->grid;
  const model::TransitionMatrix& matrix = *go1.mdp.contexts[0].transitions;
  const model::ExplicitModel& mdp = go1.mdp;
  const double epsilon = to_double(go1.partition->epsilon);
  std::mt19937_64 random(7);
  std::vector<std::uint32_t> index(2);
  double closest = 0;  // the largest total variation seen, as a fraction of epsilon
  for (int trial = 0; trial < 40; ++trial) {
    const std::size_t cell = random() % grid.num_cells();
    grid.index_of(cell, index);
    for (model::ActionIndex a = 0; a < ir.actions.size(); ++a) {
      const geom::AxisDynamics& step = geometry.actions[a];
      std::vector<double> centre_row(grid.num_cells() + 1, 0);
      for (auto e = matrix.edges_begin(static_cast<model::StateIndex>(cell), a);
           e < matrix.edges_end(static_cast<model::StateIndex>(cell), a); ++e)
        centre_row[matrix.edge_target[e]] = to_double(mdp.values[matrix.edge_probability[e]]);
      for (int corner = 0; corner < 4; ++corner) {
        double v[2];
        for (std::size_t i = 0; i < 2; ++i)
          v[i] = grid.breaks_double(i)[index[i] + ((corner >> i) & 1)];
        // Per axis: the probability of each interval, for a uniform successor interval.
        std::vector<double> axis[2];
        for (std::size_t i = 0; i < 2; ++i) {
          double mean = to_double(step.offset[i]);
          for (std::size_t j = 0; j < 2; ++j)
            mean += to_double(step.matrix[i][j]) * v[j];
          const double low = mean + to_double(step.disturbance[i].uniform.low);
          const double high = mean + to_double(step.disturbance[i].uniform.high);
          const std::vector<double>& t = grid.breaks_double(i);
          for (std::size_t k = 0; k + 1 < t.size(); ++k)
            axis[i].push_back(std::max(0.0, std::min(high, t[k + 1]) - std::max(low, t[k])) /
                              (high - low));
        }
        double variation = 0;
        double inside = 0;
        for (std::size_t k0 = 0; k0 < axis[0].size(); ++k0) {
          for (std::size_t k1 = 0; k1 < axis[1].size(); ++k1) {
            const double p = axis[0][k0] * axis[1][k1];
            const std::uint32_t target[2] = {static_cast<std::uint32_t>(k0),
                                             static_cast<std::uint32_t>(k1)};
            inside += p;
            variation += std::abs(p - centre_row[grid.cell_of(target)]);
          }
        }
        variation += std::abs((1 - inside) - centre_row[grid.num_cells()]);
        variation /= 2;
        ASSERT_LE(variation, epsilon + 1e-9) << "cell " << cell << ", corner " << corner;
        closest = std::max(closest, variation / epsilon);
      }
    }
  }
  EXPECT_GT(closest, 0.5) << "the bound is far looser than the worst vertex";
}

// A target no grid can meet (x reads y, which moves without a disturbance and so keeps its
// pre-image cells, here the whole [0, 4]): the refinement stops at the budget, says the
// target was not met, and does not try to build an unbounded number of breakpoints.
TEST(GeomGrid, AnUnreachableTargetStopsAtTheBudget) {
  const model::ModelIR ir = test::check_spec_text_ir(R"(
mdp mixed {
  continuous x : [0 .. 10];
  continuous y : [0 .. 4];
  actions go;
  disturbance x in [-1 .. 1];
  dynamics [go] { x' = x + y; }
  region goal = x >= 3 & x <= 4;
}
catalog { context at_goal { reward goal : 1; } }
)");
  std::string error;
  auto partition =
      geom::partition_grid(geometry_of(ir, 0), {.epsilon = 0.1, .max_cells = 1000}, error);
  ASSERT_TRUE(partition) << error;
  EXPECT_FALSE(partition->met);
  EXPECT_LE(partition->grid.num_cells(), 1000U);
  EXPECT_GE(to_double(partition->epsilon), 1.0);  // y's half-width 2 over x's width 2
}

}  // namespace
}  // namespace oasis
