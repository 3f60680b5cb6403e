#pragma once
// The sound error bound of a polytope cell (docs/geometry.md, "The polytope path").
//
// The finite MDP gives cell C under action a the successor distribution of one point x_C
// (C's representative). From any other point x of C the successor is uniform on the box
// M x + t + W (W: the disturbance intervals on the disturbed axes D, a point on the others,
// U). When membership of a successor in every cell, and in the domain, depends on its D
// coordinates alone over the whole swept set S_C = M C + t + W (no splitting hyperplane with
// a non-zero U coefficient cuts S_C, and S_C is inside or outside the domain's U range as a
// whole), the two distributions differ by a shift δ = M (x - x_C) of a uniform box, so
//
//     ε_C,a = max over the vertices v of C of Σ_{i in D} |(M (v - x_C))_i| / w_i
//
// bounds the total variation between the row and the successor distribution of every point
// of C (capped at 1). When that condition fails the bound is 1: the cell must be split,
// and, when the offending hyperplane has no D coefficient, its pre-image under the action
// separates C's points by the side their successors land on (the bisimulation split).

#include <cstddef>
#include <optional>

#include "geom/bsp_tree.hpp"
#include "geom/polytope_geometry.hpp"

namespace oasis::geom {

// `range` (of normal . z over the images of some points) widened by the step's disturbance
// box: the range of normal . z over every successor of those points.
void add_disturbance(const AffineStep& step, const std::vector<Rational>& normal,
                     ValueRange& range);

struct CellErrorBound {
  Rational epsilon;  // in [0, 1]; 0 for a row that is exact from every point of the cell
  // When epsilon is 1 because a hyperplane reading only undisturbed axes cuts the cell's
  // image (a splitting hyperplane, or the edge of the domain): its pre-image under the
  // action, which cuts the cell's interior.
  std::optional<HalfSpace> preimage_split;
};

CellErrorBound cell_error_bound(const PolytopeGeometry& geometry, const BspTree& tree,
                                std::size_t cell, std::size_t action);

// The largest bound over every cell and action of the tree (0 when every row is exact).
Rational partition_error_bound(const PolytopeGeometry& geometry, const BspTree& tree);

}  // namespace oasis::geom
