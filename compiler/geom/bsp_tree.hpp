#pragma once
// A partition of a box domain into convex cells, kept as a binary space partition: every
// internal node holds a half-space a·x <= c and two children, every leaf one cell.
//
// Boundary rule: a point with a·x <= c goes to the `below` child, any other point to
// `above`. Cells are therefore closed polytopes for geometry, but as sets of points they
// lose the faces their neighbours win by this rule, and every point of the closed domain box
// reaches exactly one leaf. Points outside the domain box are `outside` (no cell). The same
// rule in doubles (rounded_nodes(), locate_rounded()) is what the runtime applies; the two
// can differ only within about one ulp of a splitting hyperplane.
//
// Every cell is full-dimensional: split() refuses a half-space that does not cut a cell's
// interior, so no empty or flat cell is ever made.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "geom/polytope.hpp"

namespace oasis::geom {

struct BspNode {
  static constexpr std::uint32_t kNone = UINT32_MAX;

  HalfSpace split;              // internal nodes only
  std::uint32_t below = kNone;  // child for a·x <= c
  std::uint32_t above = kNone;  // child for a·x > c
  std::uint32_t cell = kNone;   // leaves only: index into cells()

  [[nodiscard]] bool is_leaf() const { return cell != kNone; }
};

struct BspCell {
  Polytope polytope;            // H-representation, without redundant constraints
  std::vector<Point> vertices;  // exact, sorted
  Point representative;         // an interior point (see representative_point)
  Rational volume;              // exact
  std::uint32_t leaf = 0;       // its node
};

// The smallest and largest value of a·z over some set of points z.
struct ValueRange {
  Rational low;
  Rational high;
};

// The node in doubles: the exact coefficients rounded to nearest.
struct RoundedBspNode {
  std::vector<double> normal;
  double bound = 0;
  std::uint32_t below = BspNode::kNone;
  std::uint32_t above = BspNode::kNone;
  std::uint32_t cell = BspNode::kNone;
};

class BspTree {
 public:
  BspTree() = default;
  // One cell: the box Π [low_i, high_i] (low_i < high_i).
  BspTree(const Point& low, const Point& high);

  [[nodiscard]] std::size_t dimension() const { return low_.size(); }
  [[nodiscard]] const Point& domain_low() const { return low_; }
  [[nodiscard]] const Point& domain_high() const { return high_; }
  [[nodiscard]] const std::vector<BspNode>& nodes() const { return nodes_; }  // root: node 0
  [[nodiscard]] const std::vector<BspCell>& cells() const { return cells_; }
  [[nodiscard]] std::size_t num_cells() const { return cells_.size(); }

  // Splits cell `cell` by `half_space` when its hyperplane cuts the cell's interior: the part
  // with a·x <= c keeps index `cell`, the other becomes cell num_cells() - 1. Returns false,
  // and changes nothing, when the hyperplane misses the interior.
  bool split(std::size_t cell, const HalfSpace& half_space);

  // The cell holding `point` by the boundary rule; nullopt outside the domain box.
  [[nodiscard]] std::optional<std::size_t> locate(const Point& point) const;

  // The cells a convex set may meet, found by walking the tree: `range` gives the range of
  // a·z over the set for a node's a. A node whose hyperplane strictly separates points of
  // the set (low < c < high) sends the walk both ways and is added to `cut_nodes` when that
  // is given. A superset of the cells whose interior meets the set.
  [[nodiscard]] std::vector<std::uint32_t> cells_meeting(
      const std::function<ValueRange(const std::vector<Rational>&)>& range,
      std::vector<std::uint32_t>* cut_nodes = nullptr) const;

  // The nodes in doubles, for the runtime's point location.
  [[nodiscard]] std::vector<RoundedBspNode> rounded_nodes() const;

 private:
  BspCell make_cell(const Polytope& polytope, std::vector<Point> vertices,
                    std::uint32_t leaf) const;

  Point low_;
  Point high_;
  std::vector<BspNode> nodes_;
  std::vector<BspCell> cells_;
};

// True when every constraint reads a single axis: a cell (bounded, full-dimensional, its
// constraints its facets) is then its own bounding box.
bool is_axis_aligned(const Polytope& polytope);

// The representative point of a cell: the centre of the largest copy of its bounding box,
// scaled about its centre, inside the cell (exact LP; geom/polytope.hpp chebyshev_centre
// with the box's half-widths as the shape), moved to the shortest dyadic point within a
// sixteenth of that copy on every axis, so that numbers stay short down the tree. For the
// box cells of repeated halving this is their centre, as in the grid path; it is always an
// interior point.
Point representative_point(const Polytope& polytope, std::span<const Point> vertices);

// locate() in doubles over rounded_nodes(): nullopt outside [low, high].
std::optional<std::size_t> locate_rounded(std::span<const RoundedBspNode> nodes,
                                          std::span<const double> low, std::span<const double> high,
                                          std::span<const double> point);

}  // namespace oasis::geom
