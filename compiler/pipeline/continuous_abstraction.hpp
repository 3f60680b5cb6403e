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
#include "pipeline/continuous_options.hpp"
#include "policy/objective.hpp"

namespace oasis::pipeline {

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
