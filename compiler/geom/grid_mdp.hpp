#pragma once
// The finite MDP of a gridded context: one state per cell (the grid's row-major order) and a
// last state `outside`, absorbing with reward 0. Transition probabilities from a cell are
// those of its centre (geom/grid_refinement.hpp bounds what that costs for the other points of
// the cell): per axis the successor coordinate is uniform on an interval (exact overlaps),
// Gaussian (interval probabilities from the normal CDF, to the tolerance of
// geom/grid_gaussian_axis.hpp, carried as exact rationals), or a point for an axis the action moves
// without a disturbance; the axes are independent, so a target cell's probability is the
// product of 1-D probabilities, and the mass that leaves the domain on any axis goes to
// `outside`. Every row sums to exactly 1.
//
// The result is an ExplicitModel with one context, so that the bisimulation engine and the
// policy solver run on it unchanged: cells with equal rows merge into one block.

#include <optional>
#include <string>

#include "geom/grid.hpp"
#include "geom/grid_geometry.hpp"
#include "geom/grid_product_rows.hpp"
#include "model/explicit_model.hpp"

namespace oasis::geom {

// States: the grid's cells, then `outside` (index grid.num_cells()). Actions: the model's.
// `objective` is copied into the result. Throws nothing; may take a while for large grids
// (one row per cell and action, a product of 1-D overlap lists).
model::ExplicitModel grid_finite_mdp(const GridGeometry& geometry, const Grid& grid,
                                     const std::vector<std::string>& action_names,
                                     const model::Objective& objective);
// The same, from rows already computed in product form (they hold the exact numbers).
model::ExplicitModel grid_finite_mdp(const ProductRows& rows, const std::string& context,
                                     const std::vector<std::string>& action_names,
                                     const model::Objective& objective);

}  // namespace oasis::geom
