#include "geom/bsp_subtrees.hpp"

#include <algorithm>
#include <cassert>

namespace oasis::geom {

BspSubtrees::BspSubtrees(const BspTree& tree)
    : boxes_(tree.nodes().size()),
      first_(tree.nodes().size()),
      end_(tree.nodes().size()),
      is_box_(tree.nodes().size(), false) {
  const std::vector<BspNode>& nodes = tree.nodes();
  // Pre-order without recursion (a BSP from error-driven splits can be deep): a node's
  // subtree is then the run of nodes that follows it, and its cells a run of order_.
  std::vector<std::uint32_t> preorder;
  preorder.reserve(nodes.size());
  std::vector<std::uint32_t> pending{0};
  while (!pending.empty()) {
    const std::uint32_t index = pending.back();
    pending.pop_back();
    preorder.push_back(index);
    const BspNode& node = nodes[index];
    if (node.is_leaf()) {
      first_[index] = static_cast<std::uint32_t>(order_.size());
      order_.push_back(node.cell);
      end_[index] = first_[index] + 1;
      const auto box = bounding_box_of(tree.cells()[node.cell].vertices);
      assert(box);
      boxes_[index] = *box;
      is_box_[index] = is_axis_aligned(tree.cells()[node.cell].polytope);
    } else {
      pending.push_back(node.above);  // popped after the whole below subtree
      pending.push_back(node.below);
    }
  }
  // Children come after their parent in pre-order, so backwards every child is done first.
  for (auto it = preorder.rbegin(); it != preorder.rend(); ++it) {
    const BspNode& node = nodes[*it];
    if (node.is_leaf()) continue;
    first_[*it] = first_[node.below];
    end_[*it] = end_[node.above];
    const BoundingBox& below = boxes_[node.below];
    const BoundingBox& above = boxes_[node.above];
    BoundingBox& box = boxes_[*it];
    box = below;
    for (std::size_t j = 0; j < box.low.size(); ++j) {
      if (above.low[j] < box.low[j]) box.low[j] = above.low[j];
      if (above.high[j] > box.high[j]) box.high[j] = above.high[j];
    }
  }
  dimension_ = tree.dimension();
  near_corners_.reserve(2 * nodes.size() * dimension_);
  for (const BoundingBox& box : boxes_) {
    for (const Rational& v : box.low)
      near_corners_.push_back(v.get_d());
    for (const Rational& v : box.high)
      near_corners_.push_back(v.get_d());
  }
}

}  // namespace oasis::geom
