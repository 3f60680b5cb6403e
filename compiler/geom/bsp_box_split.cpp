#include "geom/bsp_box_split.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace oasis::geom {
namespace {

// The tree's half-spaces on the slice: a·x <= c over the free axes, the fixed coordinates
// moved into c.
class Slice {
 public:
  explicit Slice(const std::vector<std::optional<Rational>>& fixed) : fixed_(fixed) {
    for (std::size_t j = 0; j < fixed.size(); ++j)
      if (!fixed[j]) free_.push_back(j);
    near_fixed_.resize(fixed.size());
    for (std::size_t j = 0; j < fixed.size(); ++j)
      if (fixed[j]) near_fixed_[j] = fixed[j]->get_d();
  }

  [[nodiscard]] const std::vector<std::size_t>& free_axes() const { return free_; }

  // The filter: -1 when every vertex of the polygon is surely strictly below the node's
  // hyperplane, +1 when every one is surely strictly above, 0 when the doubles cannot tell
  // (then exact arithmetic decides). Each a·v - c is computed in doubles from rounded
  // inputs; its error is far below 2^-40 times the sum of the magnitudes of its terms (a
  // few roundings of 2^-53 each), plus a tiny absolute term for underflow. Infinite or NaN
  // values fail every comparison and so leave the decision to the exact path.
  template <typename Polygon>
  [[nodiscard]] int side_of(const RoundedBspNode& node, const Polygon& polygon) const {
    double c = node.bound;
    double scale = std::abs(c);
    for (std::size_t j = 0; j < fixed_.size(); ++j) {
      if (!fixed_[j]) continue;
      const double term = node.normal[j] * near_fixed_[j];
      c -= term;
      scale += std::abs(term);
    }
    const double a0 = node.normal[free_[0]];
    const double a1 = node.normal[free_[1]];
    int below = 0;
    int above = 0;
    for (const auto& v : polygon) {
      const double x = a0 * v.near_x;
      const double y = a1 * v.near_y;
      const double margin = (scale + std::abs(x) + std::abs(y)) * 0x1p-40 + 0x1p-1000;
      const double value = x + y - c;
      if (value < -margin) {
        ++below;
      } else if (value > margin) {
        ++above;
      } else {
        return 0;
      }
    }
    if (below == 0) return 1;
    return above == 0 ? -1 : 0;
  }

  // Writes the restricted coefficients into `a` (one per free axis) and the bound into `c`.
  void restrict(const HalfSpace& h, std::array<Rational, 2>& a, Rational& c) const {
    c = h.bound;
    std::size_t k = 0;
    for (std::size_t j = 0; j < fixed_.size(); ++j) {
      if (fixed_[j]) {
        if (sgn(h.normal[j]) != 0) c -= h.normal[j] * *fixed_[j];
      } else {
        a[k++] = h.normal[j];
      }
    }
  }

 private:
  const std::vector<std::optional<Rational>>& fixed_;
  std::vector<std::size_t> free_;
  std::vector<double> near_fixed_;
};

// The line a0 x + a1 y = c.
struct Line {
  Rational a0;
  Rational a1;
  Rational c;
};

// A polygon's vertex and the line its outgoing edge lies on (an index into the walk's lines).
// Crossings are computed from two lines, never from earlier crossings, so their numbers
// stay as short as the lines' coefficients however deep the walk goes.
struct Vertex {
  Rational x;
  Rational y;
  std::uint32_t edge = 0;
  double near_x = 0;  // x and y rounded, for the filter
  double near_y = 0;
};

Vertex vertex(Rational x, Rational y, std::uint32_t edge) {
  const double near_x = x.get_d();
  const double near_y = y.get_d();
  return {std::move(x), std::move(y), edge, near_x, near_y};
}

// The common point of two lines that are not parallel (Cramer's rule).
Vertex crossing(const Line& l, const Line& m, std::uint32_t edge) {
  const Rational det = l.a0 * m.a1 - m.a0 * l.a1;
  return vertex((l.c * m.a1 - m.c * l.a1) / det, (l.a0 * m.c - m.a0 * l.c) / det, edge);
}
using Polygon = std::vector<Vertex>;

// Twice the signed area, Σ x_i (y_{i+1} - y_{i-1}) (the shoelace sum regrouped: n products
// of long rationals instead of 2n); pieces keep the box's counter-clockwise orientation.
Rational twice_area(const Polygon& polygon, Rational& term) {
  Rational sum = 0;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    term = polygon[(i + 1) % n].y - polygon[(i + n - 1) % n].y;
    term *= polygon[i].x;
    sum += term;
  }
  return sum;
}

// Sutherland–Hodgman against the line `cut` (index into `lines`), keeping both sides:
// `side[i]` is a·v_i - c. A vertex on the line goes to both pieces; an edge whose ends lie
// strictly on opposite sides adds its crossing point to both. In each piece the edge from
// where it leaves the other side to where it comes back lies on the cut.
void clip(const Polygon& polygon, const std::vector<Rational>& side, const std::vector<Line>& lines,
          std::uint32_t cut, Polygon& below, Polygon& above) {
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const std::size_t j = (i + 1) % polygon.size();
    const int si = sgn(side[i]);
    const int sj = sgn(side[j]);
    const Vertex& v = polygon[i];
    if (si <= 0) {
      below.push_back(v);
      if (si == 0 && sj > 0) below.back().edge = cut;
    }
    if (si >= 0) {
      above.push_back(v);
      if (si == 0 && sj < 0) above.back().edge = cut;
    }
    if (si * sj >= 0) continue;
    Vertex point = crossing(lines[v.edge], lines[cut], v.edge);
    (si < 0 ? above : below).push_back(point);  // entering that piece: on along the edge
    point.edge = cut;                           // leaving this one: along the cut
    (si < 0 ? below : above).push_back(std::move(point));
  }
}

// Where a polygon's vertices lie against the line a0 x + a1 y = c: side[i] = a·v_i - c
// (`term` is scratch), and whether any is strictly below or strictly above.
struct Sides {
  bool any_below = false;
  bool any_above = false;
};

Sides sides_of(const Polygon& polygon, const Rational& a0, const Rational& a1, const Rational& c,
               std::vector<Rational>& side, Rational& term) {
  Sides sides;
  side.resize(polygon.size());
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    side[i] = a0 * polygon[i].x;
    term = a1 * polygon[i].y;
    side[i] += term;
    side[i] -= c;
    sides.any_below = sides.any_below || sgn(side[i]) < 0;
    sides.any_above = sides.any_above || sgn(side[i]) > 0;
  }
  return sides;
}

// The box [from, to] in two dimensions as a counter-clockwise polygon, with the lines of its
// edges (y = from1, x = to0, y = to1, x = from0) that its vertices refer to.
struct BoxPolygon {
  Polygon polygon;
  std::vector<Line> lines;
};

BoxPolygon box_polygon(const Point& from, const Point& to) {
  BoxPolygon box;
  box.polygon = {vertex(from[0], from[1], 0), vertex(to[0], from[1], 1), vertex(to[0], to[1], 2),
                 vertex(from[0], to[1], 3)};
  box.lines = {{0, 1, from[1]}, {1, 0, to[0]}, {0, 1, to[1]}, {1, 0, from[0]}};
  return box;
}

void polygon_pieces(const BspTree& tree, std::span<const RoundedBspNode> rounded,
                    const Slice& slice, Polygon box, std::vector<Line> lines, BoxPieces& found) {
  std::vector<std::pair<std::uint32_t, Polygon>> pending;
  pending.emplace_back(0, std::move(box));
  std::array<Rational, 2> a;
  Rational c;
  Rational term;
  std::vector<Rational> side;
  while (!pending.empty()) {
    auto [index, polygon] = std::move(pending.back());
    pending.pop_back();
    const BspNode& node = tree.nodes()[index];
    if (node.is_leaf()) {
      Rational area = abs(twice_area(polygon, term)) / 2;
      if (sgn(area) > 0) found.cut.push_back({node.cell, std::move(area)});
      continue;
    }
    if (!rounded.empty()) {
      const int side_in_doubles = slice.side_of(rounded[index], polygon);
      if (side_in_doubles != 0) {
        pending.emplace_back(side_in_doubles < 0 ? node.below : node.above, std::move(polygon));
        continue;
      }
    }
    slice.restrict(node.split, a, c);
    const Sides sides = sides_of(polygon, a[0], a[1], c, side, term);
    if (!sides.any_above) {
      pending.emplace_back(node.below, std::move(polygon));
    } else if (!sides.any_below) {
      pending.emplace_back(node.above, std::move(polygon));
    } else {
      Polygon below;
      Polygon above;
      below.reserve(polygon.size() + 1);
      above.reserve(polygon.size() + 1);
      lines.push_back({a[0], a[1], c});
      clip(polygon, side, lines, static_cast<std::uint32_t>(lines.size() - 1), below, above);
      pending.emplace_back(node.below, std::move(below));
      pending.emplace_back(node.above, std::move(above));
    }
  }
}

// The same walk for an interval [low, high] on the one free axis.
void interval_pieces(const BspTree& tree, const Slice& slice, const Rational& low,
                     const Rational& high, BoxPieces& found) {
  std::vector<std::pair<std::uint32_t, std::pair<Rational, Rational>>> pending;
  pending.push_back({0, {low, high}});
  std::array<Rational, 2> a;
  Rational c;
  while (!pending.empty()) {
    auto [index, piece] = std::move(pending.back());
    pending.pop_back();
    auto& [from, to] = piece;
    const BspNode& node = tree.nodes()[index];
    if (node.is_leaf()) {
      Rational length = to - from;
      if (sgn(length) > 0) found.cut.push_back({node.cell, std::move(length)});
      continue;
    }
    slice.restrict(node.split, a, c);
    if (sgn(a[0]) == 0) {  // constant on the slice: all below or all above
      pending.push_back({sgn(c) >= 0 ? node.below : node.above, std::move(piece)});
      continue;
    }
    const Rational cut = c / a[0];  // a·x <= c  ⟺  x <= cut (a > 0) or x >= cut (a < 0)
    const bool increasing = sgn(a[0]) > 0;
    const std::uint32_t left = increasing ? node.below : node.above;
    const std::uint32_t right = increasing ? node.above : node.below;
    if (to <= cut) {
      pending.push_back({left, std::move(piece)});
    } else if (from >= cut) {
      pending.push_back({right, std::move(piece)});
    } else {
      pending.push_back({left, {from, cut}});
      pending.push_back({right, {cut, to}});
    }
  }
}

// a <= b, from a and b and their truncations to doubles (each within one ulp): the doubles
// decide unless they are within a few ulps of each other, then the exact numbers do.
bool at_most(double near_a, const Rational& a, double near_b, const Rational& b) {
  const double margin = (std::abs(near_a) + std::abs(near_b)) * 0x1p-50 + 0x1p-1000;
  if (near_a < near_b - margin) return true;
  if (near_a > near_b + margin) return false;
  return a <= b;
}

// The piece of `box` (with its lines) inside a convex cell: the box clipped by each of the
// cell's constraints in turn. Its area, 0 when they do not meet in an open set.
Rational clipped_area(Polygon box, std::vector<Line> lines, const Polytope& cell) {
  std::vector<Rational> side;
  Rational term;
  for (const HalfSpace& h : cell.constraints()) {
    const Sides sides = sides_of(box, h.normal[0], h.normal[1], h.bound, side, term);
    if (!sides.any_above) continue;
    if (!sides.any_below) return 0;
    Polygon below;
    Polygon above;
    lines.push_back({h.normal[0], h.normal[1], h.bound});
    clip(box, side, lines, static_cast<std::uint32_t>(lines.size() - 1), below, above);
    box = std::move(below);
  }
  return abs(twice_area(box, term)) / 2;
}

// The walk by the subtrees' boxes when no axis is fixed: a node whose box misses the open box
// [from, to] has no piece of it, one whose box lies inside it is whole, a leaf whose cell is
// a box gets the product of the overlaps, and only the other leaves, few, are clipped. No
// polygon is carried down the tree.
void box_walk(const BspTree& tree, const BspSubtrees& subtrees, const Point& from, const Point& to,
              BoxPieces& found) {
  const std::size_t d = from.size();
  std::vector<double> near_from(d);
  std::vector<double> near_to(d);
  for (std::size_t k = 0; k < d; ++k) {
    near_from[k] = from[k].get_d();
    near_to[k] = to[k].get_d();
  }
  std::vector<std::uint32_t> pending{0};
  found.cut.reserve(64);
  while (!pending.empty()) {
    const std::uint32_t index = pending.back();
    pending.pop_back();
    const BoundingBox& box = subtrees.box(index);
    const auto low = subtrees.near_low(index);
    const auto high = subtrees.near_high(index);
    bool inside = true;
    bool misses = false;
    for (std::size_t k = 0; k < d && !misses; ++k) {
      misses = at_most(high[k], box.high[k], near_from[k], from[k]) ||
               at_most(near_to[k], to[k], low[k], box.low[k]);
      inside = inside && at_most(near_from[k], from[k], low[k], box.low[k]) &&
               at_most(high[k], box.high[k], near_to[k], to[k]);
    }
    if (misses) continue;
    if (inside) {
      found.whole_subtrees.push_back(index);
      continue;
    }
    const BspNode& node = tree.nodes()[index];
    if (!node.is_leaf()) {
      pending.push_back(node.above);
      pending.push_back(node.below);
      continue;
    }
    Rational measure = 1;
    if (subtrees.is_box(index)) {
      for (std::size_t k = 0; k < d; ++k)
        measure *= std::min(box.high[k], to[k]) - std::max(box.low[k], from[k]);
    } else {  // two axes: a one-axis cell is an interval, always a box
      auto [corners, lines] = box_polygon(from, to);
      measure =
          clipped_area(std::move(corners), std::move(lines), tree.cells()[node.cell].polytope);
    }
    if (sgn(measure) > 0) found.cut.push_back({node.cell, std::move(measure)});
  }
}

}  // namespace

std::optional<BoxPieces> split_box(const BspTree& tree,
                                   const std::vector<std::optional<Rational>>& fixed,
                                   const Point& low, const Point& high,
                                   std::span<const RoundedBspNode> rounded,
                                   const BspSubtrees* subtrees) {
  const Slice slice(fixed);
  const std::vector<std::size_t>& axes = slice.free_axes();
  if (axes.empty() || axes.size() > 2) return std::nullopt;
  // The box inside the domain: outside it no cell has a piece.
  Point from(axes.size());
  Point to(axes.size());
  for (std::size_t k = 0; k < axes.size(); ++k) {
    from[k] = std::max(low[k], tree.domain_low()[axes[k]]);
    to[k] = std::min(high[k], tree.domain_high()[axes[k]]);
    if (from[k] >= to[k]) return BoxPieces{};
  }
  BoxPieces found;
  found.inside = 1;
  for (std::size_t k = 0; k < axes.size(); ++k)
    found.inside *= to[k] - from[k];
  // A subtree's box is over every axis, so it says nothing of a slice.
  if (subtrees != nullptr && axes.size() == tree.dimension()) {
    box_walk(tree, *subtrees, from, to, found);
    return found;
  }
  if (axes.size() == 1) {
    interval_pieces(tree, slice, from[0], to[0], found);
  } else {
    auto [box, lines] = box_polygon(from, to);
    polygon_pieces(tree, rounded, slice, std::move(box), std::move(lines), found);
  }
  return found;
}

std::optional<std::vector<CellMeasure>> box_cell_measures(
    const BspTree& tree, const std::vector<std::optional<Rational>>& fixed, const Point& low,
    const Point& high, std::span<const RoundedBspNode> rounded, const BspSubtrees* subtrees) {
  auto pieces = split_box(tree, fixed, low, high, rounded, subtrees);
  if (!pieces) return std::nullopt;
  std::vector<CellMeasure> found = std::move(pieces->cut);
  for (const std::uint32_t node : pieces->whole_subtrees)
    for (const std::uint32_t cell : subtrees->cells(node))
      found.push_back({cell, tree.cells()[cell].volume});
  std::sort(found.begin(), found.end(),
            [](const CellMeasure& p, const CellMeasure& q) { return p.cell < q.cell; });
  return found;
}

}  // namespace oasis::geom
