#pragma once
// One context of a continuous model, abstracted end to end: the variables it attends to
// (geom/relevance.hpp), a grid on them meeting the error target (geom/grid_refinement.hpp)
// or, when the context is not product-structured, convex polytope cells (the CGAL path,
// geom/polytope_partition.hpp), the finite MDP of the cells (geom/grid_mdp.hpp,
// geom/polytope_mdp.hpp), its coarsest bisimulation (cells with
// equal rows merge into one block) and the policy solved on the quotient. The result holds
// plain values only (cell_partition.hpp): the geometry stays in this layer and below.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "model/explicit_model.hpp"
#include "model/model_ir.hpp"
#include "pipeline/cell_partition.hpp"
#include "policy/objective.hpp"

namespace oasis::pipeline {

inline constexpr std::size_t kDefaultGridCells = 200'000;
inline constexpr std::size_t kDefaultPolytopeCells = 2'000;

struct ContinuousOptions {
  double epsilon = 0.1;  // the error bound to reach per context
  // Cells per context at most; unset: kDefaultGridCells on the grid path,
  // kDefaultPolytopeCells on the polytope path (exact polytope work per cell is far dearer).
  std::optional<std::size_t> max_cells;
  bool attention = true;  // false: partition the full state (the baseline)
  policy::PolicyOptions policy;
  // Called as each stage of a context ends (from the thread abstracting it, so possibly
  // from several threads at once): the context, what was done, and its seconds.
  std::function<void(const std::string& context, const std::string& done, double seconds)> progress;
  // Called (from the same threads) as soon as a context's refinement is known to stop above
  // the error target, before the long stages after it: the context and why.
  std::function<void(const std::string& context, const std::string& warning)> warn;
};

struct StageSeconds {
  double grid = 0;
  double finite_mdp = 0;
  double bisimulation = 0;
  double policy = 0;
};

struct ContinuousAbstraction {
  std::string context;
  // The relevant variables (geom/relevance.hpp): the grid's axes, in order, and their names.
  std::vector<std::uint32_t> axes;
  std::vector<std::string> axis_names;
  bool projection_exact = true;  // the projection onto `axes` is an exact bisimulation
  CellPartition cells;           // in plain values: what the emitters read
  Rational epsilon;              // the sound bound on every row's error (0: exact bisimulation)
  bool met = false;              // epsilon <= the target
  std::vector<std::uint32_t> cell_block;  // [cells] the block of every cell
  std::uint32_t outside_block = 0;        // the block of `outside`
  std::uint32_t num_blocks = 0;
  std::vector<double> block_reward;   // [blocks]
  std::vector<std::uint32_t> policy;  // [blocks], rt::kNoAction never (every action enabled)
  std::vector<double> value;          // [blocks]
  model::ExplicitModel quotient;      // over blocks: the transition rows, for analysis
  std::size_t finite_edges = 0;       // edges of the finite MDP before quotienting
  StageSeconds seconds;

  [[nodiscard]] std::size_t num_cells() const { return cells.num_cells(); }
  [[nodiscard]] bool exact() const { return sgn(epsilon) == 0 && projection_exact; }
};

// nullopt with `error` when the context is outside what the geometry path handles, or the
// partition needs more cells than allowed.
std::optional<ContinuousAbstraction> abstract_context(const model::ModelIR& ir, std::size_t context,
                                                      const ContinuousOptions& options,
                                                      std::string& error);

}  // namespace oasis::pipeline
