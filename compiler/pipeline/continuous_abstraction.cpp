#include "pipeline/continuous_abstraction.hpp"

#include <chrono>
#include <cstdio>

#include "bisim/quotient.hpp"
#include "bisim/refinement.hpp"
#include "geom/context_geometry.hpp"
#include "geom/finite_mdp.hpp"
#include "geom/grid_refinement.hpp"
#include "policy/value_iteration.hpp"

namespace oasis::pipeline {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point& start) {
  const Clock::time_point now = Clock::now();
  const double seconds = std::chrono::duration<double>(now - start).count();
  start = now;
  return seconds;
}

std::string describe_grid(const geom::Grid& grid, const Rational& epsilon) {
  char text[96];
  std::snprintf(text, sizeof text, "grid of %zu cells, epsilon %.4g", grid.num_cells(),
                to_double(epsilon));
  return text;
}

}  // namespace

std::optional<ContinuousAbstraction> abstract_context(const model::ModelIR& ir, std::size_t context,
                                                      const ContinuousOptions& options,
                                                      std::string& error) {
  Clock::time_point start = Clock::now();
  ContinuousAbstraction result;
  result.context = ir.contexts[context].name;
  result.relevance =
      options.attention ? geom::analyse_relevance(ir, context) : geom::full_state(ir);
  const auto geometry = geom::context_geometry(ir, context, result.relevance, error);
  if (!geometry) return std::nullopt;
  result.axis_names = geometry->axis_names;
  auto partition = geom::partition_grid(*geometry, {options.epsilon, options.max_cells}, error);
  if (!partition) return std::nullopt;
  result.epsilon = partition->epsilon;
  result.met = partition->met;
  result.grid = std::move(partition->grid);
  result.seconds.grid = seconds_since(start);
  const auto report = [&](const std::string& done, double seconds) {
    if (options.progress) options.progress(result.context, done, seconds);
  };
  report(describe_grid(result.grid, result.epsilon), result.seconds.grid);

  const model::ExplicitModel mdp =
      geom::finite_mdp(*geometry, result.grid, ir.actions, ir.objective);
  result.finite_edges = mdp.contexts[0].transitions->num_edges();
  result.seconds.finite_mdp = seconds_since(start);
  report("finite MDP, " + std::to_string(result.finite_edges) + " edges",
         result.seconds.finite_mdp);

  const bisim::Partition blocks = bisim::coarsest_bisimulation(mdp, 0);
  const std::size_t cells = result.grid.num_cells();
  result.cell_block.assign(blocks.block_of.begin(), blocks.block_of.begin() + cells);
  result.outside_block = blocks.block_of[cells];
  result.num_blocks = blocks.num_blocks;
  result.quotient = bisim::build_quotient(mdp, 0, blocks);
  result.seconds.bisimulation = seconds_since(start);
  report("quotient, " + std::to_string(result.num_blocks) + " blocks", result.seconds.bisimulation);

  result.block_reward.reserve(result.num_blocks);
  for (std::uint32_t z = 0; z < result.num_blocks; ++z)
    result.block_reward.push_back(
        to_double(result.quotient.values[result.quotient.contexts[0].rewards.state[z]]));
  policy::Policy solved = policy::solve(result.quotient, 0, options.policy);
  if (!solved.converged) {
    error = "context '" + result.context + "': value iteration did not converge";
    return std::nullopt;
  }
  result.policy = std::move(solved.action);
  result.value = std::move(solved.value);
  result.seconds.policy = seconds_since(start);
  report("policy, " + std::to_string(solved.iterations) + " sweeps", result.seconds.policy);
  return result;
}

}  // namespace oasis::pipeline
