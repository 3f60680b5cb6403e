#include "pipeline/continuous_abstraction.hpp"

#include <chrono>
#include <cstdio>

#include "bisim/quotient.hpp"
#include "bisim/refinement.hpp"
#include "geom/grid_geometry.hpp"
#include "geom/grid_mdp.hpp"
#include "geom/grid_product_rows.hpp"
#include "geom/grid_refinement.hpp"
#include "geom/polytope_partition.hpp"
#include "geom/polytope_walk_rows.hpp"
#include "geom/relevance.hpp"
#include "oasis/rt/bsp_locator.hpp"
#include "pipeline/compact_row_forms.hpp"
#include "pipeline/product_form.hpp"
#include "pipeline/stage_clock.hpp"
#include "policy/value_iteration.hpp"

namespace oasis::pipeline {
namespace {

using Clock = StageClock;

std::string describe_partition(const ContinuousAbstraction& abstraction) {
  char text[96];
  std::snprintf(text, sizeof text, "%s of %zu cells, epsilon %.4g",
                abstraction.cells.bsp ? "polytope partition" : "grid", abstraction.num_cells(),
                to_double(abstraction.epsilon));
  return text;
}

// "0.41", "1.2e-05": a bound in a message.
std::string short_number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

// Why a context's partition stops above the target, said before the stages after it.
std::string above_target(const ContinuousAbstraction& abstraction, std::size_t max_cells,
                         double target) {
  return "the cell budget of " + std::to_string(max_cells) + " cells stops the refinement at " +
         std::to_string(abstraction.num_cells()) + " cells with a bound of " +
         short_number(to_double(abstraction.epsilon)) + ", above the target " +
         short_number(target) + "; raise --max-cells (or the spec's max_cells) to reach it" +
         // Rows of probabilities never differ by more than 1: such a bound guarantees nothing.
         (to_double(abstraction.epsilon) >= 1 ? " (a bound of 1 or more guarantees nothing)" : "");
}

// The grid's breakpoints as doubles: a grid abstraction's cells, or the polytope path's box.
CellPartition grid_cells(const geom::Grid& grid) {
  CellPartition cells;
  for (std::size_t i = 0; i < grid.dimension(); ++i)
    cells.breaks.push_back(grid.breaks_double(i));
  return cells;
}

BspArrays bsp_arrays(const geom::BspTree& tree) {
  BspArrays bsp;
  bsp.dimension = static_cast<std::uint32_t>(tree.dimension());
  for (const geom::RoundedBspNode& node : tree.rounded_nodes()) {
    const bool leaf = node.cell != geom::BspNode::kNone;
    for (std::size_t i = 0; i < tree.dimension(); ++i)
      bsp.normal.push_back(leaf ? 0.0 : node.normal[i]);
    bsp.bound.push_back(leaf ? 0.0 : node.bound);
    bsp.below.push_back(leaf ? 0 : node.below);
    bsp.above.push_back(leaf ? 0 : node.above);
    bsp.cell.push_back(leaf ? node.cell : rt::kInternalNode);
  }
  return bsp;
}

PolytopeCell polytope_cell(const geom::BspCell& cell) {
  PolytopeCell plain;
  for (const geom::HalfSpace& row : cell.polytope.constraints()) {
    std::vector<double>& a = plain.rows.emplace_back();
    for (const Rational& coefficient : row.normal)
      a.push_back(to_double(coefficient));
    plain.bounds.push_back(to_double(row.bound));
  }
  for (const geom::Point& vertex : cell.vertices) {
    std::vector<double>& corner = plain.corners.emplace_back();
    for (const Rational& x : vertex)
      corner.push_back(to_double(x));
  }
  return plain;
}

// The polytope path's cells: the domain box, refined by the tree.
CellPartition polytope_cells(const geom::Grid& box, const geom::BspTree& tree) {
  CellPartition cells = grid_cells(box);
  cells.bsp = bsp_arrays(tree);
  for (const geom::BspCell& cell : tree.cells())
    cells.polytopes.push_back(polytope_cell(cell));
  return cells;
}

}  // namespace

namespace {

// The context solved on compact rows (pipeline/product_form.hpp) when `options` want them for
// rows of `edges` edges and the proof goes through: whether that succeeded. nullopt when the
// caller is to materialise the rows. `kept` says what the compact rows hold.
std::optional<bool> solve_compact(const CompactRows& rows, std::size_t edges,
                                  const std::string& kept, const std::string& form,
                                  const model::ModelIR& ir, const ContinuousOptions& options,
                                  ContinuousAbstraction& result, Clock::time_point& start,
                                  std::string& error) {
  if (!wants_product_form(edges, ir, options)) return std::nullopt;
  result.finite_edges = edges;
  result.seconds.finite_mdp = seconds_since(start);
  if (options.progress) {
    options.progress(result.context, describe_partition(result), result.seconds.grid);
    options.progress(result.context, kept + " for " + std::to_string(edges) + " edges",
                     result.seconds.finite_mdp);
  }
  switch (solve_in_product_form(rows, form, ir, options, result, error)) {
    case ProductOutcome::kSolved:
      return true;
    case ProductOutcome::kFailed:
      return false;
    case ProductOutcome::kNotDiscrete:
      break;
  }
  return std::nullopt;
}

// The grid path: product-structured contexts (box rewards, moves along single axes). The rows
// stay in product form when options ask for it and the proof of pipeline/product_form.hpp goes
// through: then `result` is complete and `mdp` stays empty. Otherwise `mdp` is the
// materialised finite MDP.
bool partition_by_grid(const geom::GridGeometry& geometry, const model::ModelIR& ir,
                       const ContinuousOptions& options, ContinuousAbstraction& result,
                       Clock::time_point& start, std::optional<model::ExplicitModel>& mdp,
                       std::string& error) {
  result.axis_names = geometry.axis_names;
  const ContinuousTarget& target = options.target;
  auto partition = geom::partition_grid(
      geometry, {.epsilon = target.epsilon, .max_cells = target.grid_cells}, error);
  if (!partition) return false;
  result.epsilon = partition->epsilon;
  result.met = partition->met;
  result.cells = grid_cells(partition->grid);
  if (!result.met && options.warn)
    options.warn(result.context, above_target(result, target.grid_cells, target.epsilon));
  result.seconds.grid = seconds_since(start);
  // The rows are worked out once, in product form; they are materialised from it when needed.
  const geom::ProductRows rows(geometry, partition->grid,
                               static_cast<std::uint32_t>(ir.actions.size()));
  const std::string kept = "product rows, " + std::to_string(rows.num_numbers()) + " numbers";
  if (const auto solved = solve_compact(CompactRowsOf(rows), rows.num_edges(), kept, "product rows",
                                        ir, options, result, start, error))
    return *solved;
  mdp = geom::grid_finite_mdp(rows, geometry.context, ir.actions, ir.objective);
  return true;
}

// The polytope path (CGAL): any linear reward regions and affine dynamics. The abstraction's
// grid is then the domain box, a single cell refined by the BSP. As for the grid, `result` is
// complete and `mdp` empty when the rows stay compact (here: as walks of the tree) and the
// proof goes through; otherwise `mdp` is the materialised finite MDP.
bool partition_by_polytopes(const geom::PolytopeGeometry& geometry, const model::ModelIR& ir,
                            const ContinuousOptions& options, ContinuousAbstraction& result,
                            Clock::time_point& start, std::optional<model::ExplicitModel>& mdp,
                            std::string& error) {
  result.axis_names = geometry.axis_names;
  geom::PolytopePartitionOptions refinement{.epsilon = Rational(options.target.epsilon),
                                            .max_cells = options.target.polytope_cells};
  if (options.progress || options.warn) {
    // Exact polytope work makes this the long stage: say how far it got every 100 cells, and
    // warn once, at half the budget, if the bound is still above the target.
    const Clock::time_point begun = start;
    refinement.progress = [&options, &result, &refinement, begun, last_shown = begun,
                           warned = false](std::size_t cells, std::optional<double> worst) mutable {
      if (options.warn && !warned && worst && cells >= refinement.max_cells / 2 &&
          *worst > to_double(refinement.epsilon)) {
        warned = true;
        options.warn(result.context, "half the cell budget (" + std::to_string(cells) + " of " +
                                         std::to_string(refinement.max_cells) +
                                         " cells) is spent and the worst cell's bound is " +
                                         short_number(*worst) + ", the target " +
                                         short_number(options.target.epsilon) +
                                         ": the refinement may stop above it (--max-cells)");
      }
      if (!options.progress) return;
      // Every 100 cells, and at least every 2 s: with exact numbers of thousands of digits (a
      // domain of 1e300) one split can take seconds, and silence would look like a hang.
      const Clock::time_point now = Clock::now();
      if (cells % 100 != 0 && now - last_shown < std::chrono::seconds(2)) return;
      last_shown = now;
      const double seconds = std::chrono::duration<double>(now - begun).count();
      std::string done = "refining, " + std::to_string(cells) + " polytope cells";
      if (worst) done += ", worst bound " + short_number(*worst);
      options.progress(result.context, done, seconds);
    };
  }
  auto partition = geom::partition_polytopes(geometry, refinement, error);
  if (!partition) return false;
  std::vector<std::vector<Rational>> box;
  for (std::size_t i = 0; i < geometry.dimension(); ++i)
    box.push_back({geometry.domain_low[i], geometry.domain_high[i]});
  const geom::Grid domain(std::move(box));
  result.seconds.grid = seconds_since(start);
  result.epsilon = partition->epsilon;  // max over every cell and action, as it ended
  result.met = partition->met;
  result.cells = polytope_cells(domain, partition->tree);
  if (!result.met && options.warn)
    options.warn(result.context,
                 above_target(result, refinement.max_cells, options.target.epsilon));
  // The rows are found once, as walks of the tree; they are materialised from them when
  // needed.
  const geom::PolytopeWalkRows rows(geometry, *partition);
  const std::string kept = "rows as tree walks, " + std::to_string(rows.num_entries()) + " entries";
  if (const auto solved = solve_compact(CompactRowsOf(rows), rows.num_edges(), kept, "tree walks",
                                        ir, options, result, start, error))
    return *solved;
  mdp = rows.materialise(geometry.context, ir.actions, ir.objective);
  return true;
}

}  // namespace

std::optional<ContinuousAbstraction> abstract_context(const model::ModelIR& ir, std::size_t context,
                                                      const ContinuousOptions& options,
                                                      std::string& error) {
  Clock::time_point start = Clock::now();
  ContinuousAbstraction result;
  result.context = ir.contexts[context].name;
  const geom::Relevance relevance =
      options.attention ? geom::analyse_relevance(ir, context) : geom::full_state(ir);
  result.axes = relevance.relevant;
  result.projection_exact = relevance.exact();
  std::optional<model::ExplicitModel> mdp;
  std::string grid_refusal;
  if (const auto geometry = geom::grid_geometry(ir, context, relevance, grid_refusal)) {
    if (!partition_by_grid(*geometry, ir, options, result, start, mdp, error)) return std::nullopt;
    if (!mdp) return result;  // solved on the rows in product form
  } else {
    std::string polytope_refusal;
    const auto polytopes = geom::polytope_geometry(ir, context, relevance, polytope_refusal);
    if (!polytopes) {
      // Both refusals name the context; say it once.
      const std::string named = "context ";
      if (polytope_refusal.starts_with(named) && polytope_refusal.find("': ") != std::string::npos)
        polytope_refusal.erase(0, polytope_refusal.find("': ") + 3);
      error = grid_refusal + "; and the polytope path cannot take it either: " + polytope_refusal;
      return std::nullopt;
    }
    if (!partition_by_polytopes(*polytopes, ir, options, result, start, mdp, error))
      return std::nullopt;
    if (!mdp) return result;  // solved on the rows as tree walks
  }
  result.finite_edges = mdp->contexts[0].transitions->num_edges();
  result.seconds.finite_mdp = seconds_since(start);
  const auto report = [&](const std::string& done, double seconds) {
    if (options.progress) options.progress(result.context, done, seconds);
  };
  report(describe_partition(result), result.seconds.grid);
  report("finite MDP, " + std::to_string(result.finite_edges) + " edges",
         result.seconds.finite_mdp);

  const model::Partition blocks = bisim::coarsest_bisimulation(*mdp, 0);
  const std::size_t cells = result.num_cells();
  result.cell_block.assign(blocks.block_of.begin(), blocks.block_of.begin() + cells);
  result.outside_block = blocks.block_of[cells];
  result.num_blocks = blocks.num_blocks;
  result.quotient = bisim::build_quotient(*mdp, 0, blocks);
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
