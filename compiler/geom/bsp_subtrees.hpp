#pragma once
// Every node of a BspTree seen as a subtree: the box bounding its region, exact, and its cells,
// which form one contiguous range of a depth-first order of the cells. A walk down the tree
// that finds a subtree's box inside the set it measures can take each of the subtree's cells
// whole, without descending: the rows of the polytope path (geom/bsp_box_split.hpp) meet most
// of their cells that way, and a whole cell's share is the same in every row.

#include <cstdint>
#include <span>
#include <vector>

#include "geom/bsp_tree.hpp"

namespace oasis::geom {

class BspSubtrees {
 public:
  explicit BspSubtrees(const BspTree& tree);

  // The smallest box holding the node's region (the union of its cells).
  [[nodiscard]] const BoundingBox& box(std::uint32_t node) const { return boxes_[node]; }
  // box(node)'s corners in doubles, each within one ulp of the exact (for a filter).
  [[nodiscard]] std::span<const double> near_low(std::uint32_t node) const {
    return std::span(near_corners_).subspan(2 * std::size_t{node} * dimension_, dimension_);
  }
  [[nodiscard]] std::span<const double> near_high(std::uint32_t node) const {
    return std::span(near_corners_).subspan((2 * std::size_t{node} + 1) * dimension_, dimension_);
  }
  // True for a leaf whose cell is its bounding box (a box's piece of it is a box too).
  [[nodiscard]] bool is_box(std::uint32_t node) const { return is_box_[node]; }
  // The node's cells, in depth-first order (below before above).
  [[nodiscard]] std::span<const std::uint32_t> cells(std::uint32_t node) const {
    return std::span(order_).subspan(first_[node], end_[node] - first_[node]);
  }

 private:
  std::vector<BoundingBox> boxes_;
  std::vector<std::uint32_t> first_;  // per node: [first_, end_) in order_
  std::vector<std::uint32_t> end_;
  std::vector<std::uint32_t> order_;  // the cells, depth first
  std::vector<bool> is_box_;
  std::size_t dimension_ = 0;
  std::vector<double> near_corners_;  // per node: low, then high
};

}  // namespace oasis::geom
