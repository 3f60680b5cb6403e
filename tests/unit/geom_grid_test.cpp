// The gridded abstraction of continuous contexts: the partition, its sound error bound, the
// exact probabilities of the finite MDP, and what the bisimulation engine makes of it.

#include <chrono>
#include <cmath>
#include <iostream>
#include <random>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "bisim/refinement.hpp"
#include "geom/context_geometry.hpp"
#include "geom/finite_mdp.hpp"
#include "geom/grid_refinement.hpp"
#include "geom/relevance.hpp"
#include "spec/frontend.hpp"

namespace oasis {
namespace {

[[maybe_unused]] model::ModelIR checked_text(const std::string& text) {
  SourceManager sources;
  std::ostringstream messages;
  DiagnosticEngine diagnostics(sources, messages);
  auto ir = spec::check_spec_text(sources.add("test.oasis", text), diagnostics);
  EXPECT_TRUE(ir) << messages.str();
  return ir ? std::move(*ir) : model::ModelIR{};
}

model::ModelIR go1_spec() {
  SourceManager sources;
  std::ostringstream messages;
  DiagnosticEngine diagnostics(sources, messages);
  auto ir = spec::load_spec(std::string(OASIS_SOURCE_DIR) + "/specs/go1_treat.oasis", sources,
                            diagnostics);
  EXPECT_TRUE(ir) << messages.str();
  return ir ? std::move(*ir) : model::ModelIR{};
}

geom::ContextGeometry geometry_of(const model::ModelIR& ir, std::size_t context) {
  std::string error;
  auto geometry = geom::context_geometry(ir, context, geom::analyse_relevance(ir, context), error);
  EXPECT_TRUE(geometry) << error;
  return geometry ? std::move(*geometry) : geom::ContextGeometry{};
}

TEST(GeomGrid, Go1ContextMeetsTheTarget) {
  const model::ModelIR ir = go1_spec();
  const geom::ContextGeometry geometry = geometry_of(ir, 0);
  ASSERT_EQ(geometry.dimension(), 2U);
  std::string error;
  const auto start = std::chrono::steady_clock::now();
  auto partition = geom::partition_grid(geometry, {.epsilon = 0.1, .max_cells = 100000}, error);
  ASSERT_TRUE(partition) << error;
  EXPECT_TRUE(partition->met);
  EXPECT_LE(to_double(partition->epsilon), 0.1);
  const auto gridded = std::chrono::steady_clock::now();
  const model::ExplicitModel mdp =
      geom::finite_mdp(geometry, partition->grid, ir.actions, ir.objective);
  const auto built = std::chrono::steady_clock::now();
  EXPECT_FALSE(model::find_structural_problem(mdp)) << *model::find_structural_problem(mdp);
  const bisim::Partition blocks = bisim::coarsest_bisimulation(mdp, 0);
  const auto quotiented = std::chrono::steady_clock::now();
  auto seconds = [](auto a, auto b) { return std::chrono::duration<double>(b - a).count(); };
  std::cout << "cells " << partition->grid.num_cells() << ", epsilon "
            << to_double(partition->epsilon) << ", edges "
            << mdp.contexts[0].transitions->num_edges() << ", blocks " << blocks.num_blocks
            << "; grid " << seconds(start, gridded) << " s, mdp " << seconds(gridded, built)
            << " s, bisimulation " << seconds(built, quotiented) << " s\n";
}

}  // namespace
}  // namespace oasis
