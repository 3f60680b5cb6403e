#pragma once
// The options of a continuous abstraction, and the one place the target and budget get their
// values: the command line wins over the spec (`epsilon e;`, `max_cells n;`), which wins over
// the defaults below (continuous_target). geom/'s partition options have no defaults of their
// own: the pipeline fills them from the ContinuousTarget it is given.

#include <cstddef>
#include <functional>
#include <optional>
#include <string>

#include "model/model_ir.hpp"
#include "policy/objective.hpp"

namespace oasis::pipeline {

// The error bound every transition row must meet, when neither the flags nor the spec give one.
inline constexpr double kDefaultEpsilon = 0.1;
// Cells per context at most, when neither gives a budget: fewer on the polytope path, whose
// exact work per cell is far dearer than a grid's.
inline constexpr std::size_t kDefaultGridCells = 200'000;
inline constexpr std::size_t kDefaultPolytopeCells = 2'000;

// What every context's partition aims at and may spend; made by continuous_target().
struct ContinuousTarget {
  double epsilon = kDefaultEpsilon;                    // the error bound to reach per context
  std::size_t grid_cells = kDefaultGridCells;          // the budget on the grid path
  std::size_t polytope_cells = kDefaultPolytopeCells;  // the budget on the polytope path
};

// The target and budget as the command line gives them; unset: not given.
struct TargetFlags {
  std::optional<double> epsilon;         // --epsilon
  std::optional<std::size_t> max_cells;  // --max-cells: one budget for both paths
};

// Setting by setting, the flag, else the spec's, else the default. A budget given by the flags
// or the spec is that of both paths.
ContinuousTarget continuous_target(const model::ModelIR& spec, const TargetFlags& flags);

// How a continuous context's rows are kept. Materialised: CSR rows, the exact partition
// refinement and the solver on them. Product: compact rows (the grid path's per-axis rows,
// geom/grid_product_rows.hpp; the polytope path's tree walks, geom/polytope_walk_rows.hpp), a
// proof by invariants that no two cells are bisimilar (bisim/discrete_proof.hpp; when it
// cannot be had, the rows are materialised after all) and value iteration on the compact
// form. Automatic: compact when the materialised rows would pass kProductRowsAbove edges per
// context; below it the rows are cheap, and catalogs stay bit for bit those of the
// materialised solver (the compact forms sum in another order, so their values differ in the
// last bits).
enum class GridRows { kAutomatic, kMaterialised, kProduct };
inline constexpr std::size_t kProductRowsAbove = std::size_t{1} << 24;

struct ContinuousOptions {
  ContinuousTarget target;
  bool attention = true;  // false: partition the full state (the baseline)
  GridRows grid_rows = GridRows::kAutomatic;
  // The quotient's transition rows are wanted (--with-transitions): a grid context in product
  // form then materialises them for the quotient alone.
  bool keep_rows = false;
  policy::PolicyOptions policy;
  // Called as each stage of a context ends (from the thread abstracting it, so possibly
  // from several threads at once): the context, what was done, and its seconds.
  std::function<void(const std::string& context, const std::string& done, double seconds)> progress;
  // Called (from the same threads) as soon as a context's refinement is known to stop above
  // the error target, before the long stages after it: the context and why.
  std::function<void(const std::string& context, const std::string& warning)> warn;
};

}  // namespace oasis::pipeline
