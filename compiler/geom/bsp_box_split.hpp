#pragma once
// The exact measure of a box's intersection with every BSP cell it meets, in one walk of the
// tree: the box (clipped to the domain) is split at every node whose hyperplane cuts it, and
// each leaf receives its piece. The pieces partition the box's part inside the domain, so
// their measures sum exactly to that part's measure.
//
// This replaces one general d-dimensional volume (vertex enumeration and Lasserre's
// recursion) per (box, target cell) for the boxes of one and two free dimensions, where the
// pieces are intervals and convex polygons: clipping and the shoelace formula are exact and
// cost a few rational operations per vertex.

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "geom/bsp_tree.hpp"

namespace oasis::geom {

struct CellMeasure {
  std::uint32_t cell = 0;
  Rational measure;  // length or area of the piece, > 0
};

// The box Π [low_k, high_k] over the free axes (those with no `fixed` value, in increasing
// order), on the slice through the `fixed` values of the other axes: every cell whose piece
// of it has positive measure, with that measure, sorted by cell. The fixed values must lie in
// the domain. nullopt when there are not one or two free axes (the general path applies).
// `rounded`, when given, is tree.rounded_nodes(): a filter in doubles then decides the side
// of most nodes without exact arithmetic (the result is the same).
std::optional<std::vector<CellMeasure>> box_cell_measures(
    const BspTree& tree, const std::vector<std::optional<Rational>>& fixed, const Point& low,
    const Point& high, std::span<const RoundedBspNode> rounded = {});

}  // namespace oasis::geom
