#pragma once
// The exact measure of a box's intersection with every BSP cell it meets, in one walk of the
// tree, two ways. On a slice (some axis fixed), or without the subtrees' boxes, the box
// (clipped to the domain) is split at every node whose hyperplane cuts it, and each leaf
// receives its piece. With every axis free and geom/bsp_subtrees.hpp at hand, the walk goes
// by the subtrees' bounding boxes instead: a subtree inside the box is named whole, a box
// cell gets the product of its overlaps, and only the other cells are clipped. Either way the
// pieces partition the box's part inside the domain, so their measures sum exactly to that
// part's measure.
//
// This replaces one general d-dimensional volume (vertex enumeration and Lasserre's
// recursion) per (box, target cell) for the boxes of one and two free dimensions, where the
// pieces are intervals and convex polygons: clipping and the shoelace formula are exact and
// cost a few rational operations per vertex.

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "geom/bsp_subtrees.hpp"
#include "geom/bsp_tree.hpp"

namespace oasis::geom {

struct CellMeasure {
  std::uint32_t cell = 0;
  Rational measure;  // length or area of the piece, > 0
};

// The box's pieces as the walk finds them.
struct BoxPieces {
  std::vector<CellMeasure> cut;  // cells the box's boundary crosses, with their piece
  // Nodes whose region is inside the box: each of their cells (BspSubtrees::cells) is a
  // piece whole.
  std::vector<std::uint32_t> whole_subtrees;
  Rational inside;  // the measure of the box's part inside the domain: Σ pieces
};

// The box Π [low_k, high_k] over the free axes (those with no `fixed` value, in increasing
// order), on the slice through the `fixed` values of the other axes, split down the tree:
// every cell whose piece of it has positive measure, once. The fixed values must lie in the
// domain. nullopt when there are not one or two free axes (the general path applies).
// `rounded`, when given, is tree.rounded_nodes(): a filter in doubles then decides the side
// of most nodes without exact arithmetic. `subtrees`, when given and no axis is fixed, lets
// the walk stop at a subtree inside the box and name it in `whole_subtrees` (otherwise every
// cell is in `cut`). Neither changes which cells are found or their measures.
std::optional<BoxPieces> split_box(const BspTree& tree,
                                   const std::vector<std::optional<Rational>>& fixed,
                                   const Point& low, const Point& high,
                                   std::span<const RoundedBspNode> rounded = {},
                                   const BspSubtrees* subtrees = nullptr);

// The same pieces as one list sorted by cell, a whole cell's measure being its volume.
std::optional<std::vector<CellMeasure>> box_cell_measures(
    const BspTree& tree, const std::vector<std::optional<Rational>>& fixed, const Point& low,
    const Point& high, std::span<const RoundedBspNode> rounded = {},
    const BspSubtrees* subtrees = nullptr);

}  // namespace oasis::geom
