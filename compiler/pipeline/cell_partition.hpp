#pragma once
// A continuous abstraction's cells in plain values. The pipeline lowers the geometry layer's
// grid and BSP into these (continuous_abstraction.cpp), and the emitters read only them:
// codegen/ never sees a geometry type.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace oasis::pipeline {

// The polytope path's BSP, rounded to doubles, in the runtime's array layout (rt::BspView).
struct BspArrays {
  std::uint32_t dimension = 0;
  std::vector<double> normal;        // [nodes * dimension]; zeros for a leaf
  std::vector<double> bound;         // [nodes]: normal . x <= bound goes below; 0 for a leaf
  std::vector<std::uint32_t> below;  // [nodes]; 0 for a leaf
  std::vector<std::uint32_t> above;  // [nodes]; 0 for a leaf
  std::vector<std::uint32_t> cell;   // [nodes]: a leaf's cell, rt::kInternalNode otherwise

  [[nodiscard]] std::size_t num_nodes() const { return cell.size(); }
  [[nodiscard]] bool is_leaf(std::size_t node) const;
};

// One polytope cell: its irredundant rows A x <= b over the grid's axes, and its corners
// (sorted, exact values rounded to the nearest double).
struct PolytopeCell {
  std::vector<std::vector<double>> rows;
  std::vector<double> bounds;
  std::vector<std::vector<double>> corners;
};

// The cells of one abstraction: a grid over its axes (cells numbered row-major, the last axis
// fastest), or on the polytope path the domain box, one grid cell, refined by a BSP.
struct CellPartition {
  std::vector<std::vector<double>> breaks;  // per axis, strictly increasing
  std::optional<BspArrays> bsp;             // the polytope path only
  std::vector<PolytopeCell> polytopes;      // [cells] on the polytope path, else empty

  [[nodiscard]] std::size_t dimension() const { return breaks.size(); }
  [[nodiscard]] std::size_t intervals(std::size_t axis) const { return breaks[axis].size() - 1; }
  [[nodiscard]] std::size_t num_cells() const;
  // Grid cells: the cell at a per-axis interval index, and back.
  [[nodiscard]] std::size_t cell_of(std::span<const std::uint32_t> index) const;
  void index_of(std::size_t cell, std::span<std::uint32_t> index) const;
  // The interval of `axis` holding x (the high end belongs to the last interval); nullopt
  // outside the axis or for NaN.
  [[nodiscard]] std::optional<std::uint32_t> locate(std::size_t axis, double x) const;
};

}  // namespace oasis::pipeline
