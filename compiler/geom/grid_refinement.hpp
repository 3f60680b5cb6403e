#pragma once
// The partition of a context's relevant box into a rectilinear grid, and its sound error
// bound (docs/geometry.md).
//
// 1. Mandatory breakpoints: the domain's ends and every reward box's edges, so that the
//    reward is constant on every cell.
// 2. Axes with a disturbance (uniform or Gaussian) are cut into equal pieces inside each
//    mandatory segment, as fine as the error target asks (or the cell budget allows).
// 3. Axes that some action moves without a disturbance (x' = a x + b) get the pre-images of
//    their breakpoints under those maps, until nothing new appears: the classic bisimulation
//    step for deterministic dynamics, which makes every cell's image fall inside one cell.
//
// The error bound of a cell C under action a: from a point x of C the successor is
// A x + b + w; moving it by δ = A (x - c) changes the probability of any set by at most
// Σ_i |δ_i| · cost_i, cost_i = 1 / w_i for a uniform disturbance of width w_i and
// 1 / (s_i √(2π)) for a Gaussian one of deviation s_i (its total variation under a shift,
// 2Φ(|δ|/2s) - 1, is concave in |δ| with slope 1/(s√(2π)) at 0); the axes are independent, so
// their distances add. With the probabilities computed at C's centre c, the whole row is off
// by at most ε_C,a = max over C's vertices v of Σ_i |(A (v - c))_i| · cost_i (axes moved
// deterministically land in one cell from every point of C, so they add nothing). This is
// monotone in C's half-widths, so the context's ε is that of the widest cell shape, per
// action; to it is added, per Gaussian axis, the tolerance of computing its probabilities in
// floating point (geom/grid_gaussian_axis.hpp).

#include <cstddef>
#include <optional>
#include <span>
#include <string>

#include "geom/grid.hpp"
#include "geom/grid_geometry.hpp"

namespace oasis::geom {

// No defaults: the caller gives both (pipeline/continuous_options.hpp holds the defaults and
// the rule that chooses between them, the spec and the command line).
struct GridTarget {
  double epsilon;         // the error bound to reach
  std::size_t max_cells;  // refuse to refine past this many cells
};

struct GridPartition {
  Grid grid;
  // The sound bound reached: max over cells and actions, exact, with the numeric tolerance of
  // Gaussian rows included.
  Rational epsilon;
  bool met = false;  // epsilon <= the target
  std::size_t preimage_rounds = 0;
};

// The total variation a unit shift of `w` costs at most: 1 / width for a uniform disturbance,
// 1 / (s·√(2π)) for a Gaussian one, rounded up (geom/grid_gaussian_axis.hpp), 0 for none.
Rational shift_cost(const Disturbance& w);

// ε_C,a for a cell of these half-widths (per relevant axis) under `action`, without the
// numeric tolerance of Gaussian rows.
Rational cell_error(const AxisDynamics& action, std::span<const Rational> half_widths);

// nullopt with `error` when the pre-image refinement passes the cell budget (the coarsest
// partition may be infinite, as for a shift by an irrational-looking step).
std::optional<GridPartition> partition_grid(const GridGeometry& geometry, const GridTarget& target,
                                            std::string& error);

}  // namespace oasis::geom
