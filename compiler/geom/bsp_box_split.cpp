#include "geom/bsp_box_split.hpp"

#include <algorithm>
#include <array>
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
  }

  [[nodiscard]] const std::vector<std::size_t>& free_axes() const { return free_; }

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
};

struct Vertex {
  Rational x;
  Rational y;
};
using Polygon = std::vector<Vertex>;

// Twice the signed area (shoelace); pieces keep the box's counter-clockwise orientation.
Rational twice_area(const Polygon& polygon, Rational& term) {
  Rational sum = 0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Vertex& p = polygon[i];
    const Vertex& q = polygon[(i + 1) % polygon.size()];
    term = p.x * q.y;
    sum += term;
    term = q.x * p.y;
    sum -= term;
  }
  return sum;
}

// Sutherland–Hodgman against one line, keeping both sides: `side[i]` is a·v_i - c. A vertex
// on the line goes to both pieces; an edge whose ends lie strictly on opposite sides adds
// its crossing point to both.
void clip(const Polygon& polygon, const std::vector<Rational>& side, Polygon& below,
          Polygon& above) {
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const std::size_t j = (i + 1) % polygon.size();
    const int si = sgn(side[i]);
    const int sj = sgn(side[j]);
    if (si <= 0) below.push_back(polygon[i]);
    if (si >= 0) above.push_back(polygon[i]);
    if (si * sj >= 0) continue;
    const Rational t = side[i] / (side[i] - side[j]);
    Vertex crossing{polygon[i].x + t * (polygon[j].x - polygon[i].x),
                    polygon[i].y + t * (polygon[j].y - polygon[i].y)};
    below.push_back(crossing);
    above.push_back(std::move(crossing));
  }
}

std::vector<CellMeasure> polygon_pieces(const BspTree& tree, const Slice& slice,
                                        Polygon box) {
  std::vector<CellMeasure> found;
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
      if (sgn(area) > 0) found.push_back({node.cell, std::move(area)});
      continue;
    }
    slice.restrict(node.split, a, c);
    side.resize(polygon.size());
    bool any_below = false;
    bool any_above = false;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
      side[i] = a[0] * polygon[i].x;
      term = a[1] * polygon[i].y;
      side[i] += term;
      side[i] -= c;
      any_below = any_below || sgn(side[i]) < 0;
      any_above = any_above || sgn(side[i]) > 0;
    }
    if (!any_above) {
      pending.emplace_back(node.below, std::move(polygon));
    } else if (!any_below) {
      pending.emplace_back(node.above, std::move(polygon));
    } else {
      Polygon below;
      Polygon above;
      clip(polygon, side, below, above);
      pending.emplace_back(node.below, std::move(below));
      pending.emplace_back(node.above, std::move(above));
    }
  }
  return found;
}

// The same walk for an interval [low, high] on the one free axis.
std::vector<CellMeasure> interval_pieces(const BspTree& tree, const Slice& slice,
                                         const Rational& low, const Rational& high) {
  std::vector<CellMeasure> found;
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
      if (sgn(length) > 0) found.push_back({node.cell, std::move(length)});
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
  return found;
}

}  // namespace

std::optional<std::vector<CellMeasure>> box_cell_measures(
    const BspTree& tree, const std::vector<std::optional<Rational>>& fixed, const Point& low,
    const Point& high) {
  const Slice slice(fixed);
  const std::vector<std::size_t>& axes = slice.free_axes();
  if (axes.empty() || axes.size() > 2) return std::nullopt;
  // The box inside the domain: outside it no cell has a piece.
  Point from(axes.size());
  Point to(axes.size());
  for (std::size_t k = 0; k < axes.size(); ++k) {
    from[k] = std::max(low[k], tree.domain_low()[axes[k]]);
    to[k] = std::min(high[k], tree.domain_high()[axes[k]]);
    if (from[k] >= to[k]) return std::vector<CellMeasure>{};
  }
  std::vector<CellMeasure> found;
  if (axes.size() == 1) {
    found = interval_pieces(tree, slice, from[0], to[0]);
  } else {
    Polygon box(4);  // counter-clockwise
    box[0] = {from[0], from[1]};
    box[1] = {to[0], from[1]};
    box[2] = {to[0], to[1]};
    box[3] = {from[0], to[1]};
    found = polygon_pieces(tree, slice, std::move(box));
  }
  std::sort(found.begin(), found.end(),
            [](const CellMeasure& p, const CellMeasure& q) { return p.cell < q.cell; });
  return found;
}

}  // namespace oasis::geom
