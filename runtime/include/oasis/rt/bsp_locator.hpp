// oasis/rt/bsp_locator.hpp: point location in a continuous abstraction whose cells are convex
// polytopes (the compiler's polytope path, compiler/geom/bsp_tree.hpp).
//
// Such an abstraction keeps a binary space partition of its grid's domain box: every internal
// node holds a half-space a.x <= c over the abstraction's relevant variables (the grid's axes,
// in order) and two children; every leaf is one cell. Location first checks the domain box
// (the grid, which then has a single cell; outside it the state is outside), then walks from
// the root: O(depth) dot products of `dimension` terms, no allocation, no exceptions.
//
// Boundary rule (the compiler's): a point with a.x <= c goes to `below`, any other to
// `above`; with the coefficients as stored (the exact ones rounded to nearest), so the
// compiler and the runtime can differ only within about one ulp of a splitting hyperplane.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>

#include "oasis/rt/grid_locator.hpp"

namespace oasis::rt {

/// Marks an internal node in BspView::cell.
inline constexpr std::uint32_t kInternalNode = 0xFFFFFFFFu;

/// A BSP over the relevant variables of an abstraction. A view: owns nothing. num_nodes 0
/// means no BSP: the grid's cells are the abstraction's cells.
struct BspView {
  std::uint32_t num_nodes = 0;  ///< internal nodes and leaves; the root is node 0
  std::uint32_t num_cells = 0;  ///< leaves
  /// [num_nodes * dimension] the normal a of each node (zeros for leaves), dimension being
  /// the grid's.
  const double* normal = nullptr;
  const double* bound = nullptr;         ///< [num_nodes] c
  const std::uint32_t* below = nullptr;  ///< [num_nodes] child for a.x <= c (leaves: 0)
  const std::uint32_t* above = nullptr;  ///< [num_nodes] child for a.x > c (leaves: 0)
  const std::uint32_t* cell = nullptr;   ///< [num_nodes] a leaf's cell, kInternalNode otherwise
};

/// The cell of `state` in an abstraction with this grid and BSP (either may be the only
/// partition: with bsp.num_nodes == 0 the grid's row-major cell), or kOutsideCell. Both must
/// be valid (validate_grid, validate_bsp).
inline std::uint32_t locate_partition_cell(const GridView& grid, const BspView& bsp,
                                           const double* state, std::size_t state_size) noexcept {
  const std::uint32_t grid_cell = locate_cell(grid, state, state_size);
  if (bsp.num_nodes == 0 || grid_cell == kOutsideCell) return grid_cell;
  const std::uint32_t d = grid.dimension;
  std::uint32_t node = 0;
  while (bsp.cell[node] == kInternalNode) {
    double dot = 0.0;
    for (std::uint32_t i = 0; i < d; ++i)
      dot += bsp.normal[std::size_t{node} * d + i] * state[grid.axes[i]];
    node = dot <= bsp.bound[node] ? bsp.below[node] : bsp.above[node];
  }
  return bsp.cell[node];
}

/// True when the BSP is well formed over a grid of `dimension` axes with a single cell:
/// non-null arrays, finite coefficients, children of an internal node after it (so every
/// walk ends), every cell index below num_cells and each cell at exactly one leaf (checked
/// with `scratch`, num_cells bytes, so that validation allocates nothing here).
inline bool validate_bsp(const BspView& bsp, std::uint32_t dimension,
                         unsigned char* scratch) noexcept {
  if (bsp.num_nodes == 0) return true;
  if (bsp.num_cells == 0 || bsp.normal == nullptr || bsp.bound == nullptr || bsp.below == nullptr ||
      bsp.above == nullptr || bsp.cell == nullptr || scratch == nullptr)
    return false;
  for (std::uint32_t c = 0; c < bsp.num_cells; ++c)
    scratch[c] = 0;
  std::uint32_t leaves = 0;
  for (std::uint32_t n = 0; n < bsp.num_nodes; ++n) {
    if (bsp.cell[n] != kInternalNode) {
      if (bsp.cell[n] >= bsp.num_cells || scratch[bsp.cell[n]] != 0) return false;
      scratch[bsp.cell[n]] = 1;
      ++leaves;
      continue;
    }
    if (bsp.below[n] <= n || bsp.below[n] >= bsp.num_nodes || bsp.above[n] <= n ||
        bsp.above[n] >= bsp.num_nodes || !std::isfinite(bsp.bound[n]))
      return false;
    for (std::uint32_t i = 0; i < dimension; ++i)
      if (!std::isfinite(bsp.normal[std::size_t{n} * dimension + i])) return false;
  }
  return leaves == bsp.num_cells;
}

}  // namespace oasis::rt
