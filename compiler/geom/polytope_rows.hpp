#pragma once
// One row of the polytope path's finite MDP (geom/polytope_mdp.hpp states the model): the
// successor distribution of a cell's representative x_C under an action. The successor is
// uniform on the box B = M x_C + t + W (a point on the undisturbed axes), and target cell Q
// gets vol(B ∩ Q) / vol(B), measured in the disturbed coordinates on the slice through the
// fixed undisturbed ones, exact. The mass outside the domain goes to `outside`. Candidate
// targets come from walking the BSP tree with B (geom/bsp_box_split.hpp).

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "geom/bsp_subtrees.hpp"
#include "geom/polytope_geometry.hpp"

namespace oasis::geom {

// vol(W): the product of the disturbance's widths (1 when no axis is disturbed).
Rational box_volume_of(const AffineStep& step);

// One row as the walk of the tree finds it.
struct RowParts {
  // Nodes whose region lies inside B: each of their cells Q has probability vol(Q) / vol(B),
  // the same in every row of the action. Only with `subtrees` (and no axis undisturbed).
  std::vector<std::uint32_t> whole_subtrees;
  // Every other target with its probability, exact; `outside` is index tree.num_cells().
  std::vector<std::pair<std::size_t, Rational>> shares;
};

// The row of the point `from` under `step`. `rounded`, when given, is tree.rounded_nodes()
// (made once per tree) and `subtrees` BspSubtrees(tree): they speed up the walk, not the
// result.
RowParts successor_parts(const PolytopeGeometry& geometry, const BspTree& tree,
                         const AffineStep& step, const Point& from,
                         std::span<const RoundedBspNode> rounded, const BspSubtrees* subtrees);

// The same row as one list: (cell, probability) pairs for the cells with a positive
// probability, in increasing cell order, and the probability of `outside` last with index
// tree.num_cells() when positive. For checks and for the integrator.
std::vector<std::pair<std::size_t, Rational>> successor_row(
    const PolytopeGeometry& geometry, const BspTree& tree, const AffineStep& step,
    const Point& from, std::span<const RoundedBspNode> rounded = {});

}  // namespace oasis::geom
