#include "geom/bsp_tree.hpp"

#include <algorithm>
#include <cassert>

namespace oasis::geom {
namespace {

// Only constraints that hold at least d vertices with equality can bound a facet; the others
// are redundant for a full-dimensional polytope, so the vertices give the reduction without
// a linear program.
Polytope facets_only(const Polytope& polytope, const std::vector<Point>& vertices) {
  const std::size_t d = polytope.dimension();
  std::vector<HalfSpace> kept;
  for (const HalfSpace& h : polytope.constraints()) {
    const auto tight = std::count_if(vertices.begin(), vertices.end(),
                                     [&](const Point& v) { return dot(h.normal, v) == h.bound; });
    if (static_cast<std::size_t>(tight) >= d) kept.push_back(h);
  }
  return Polytope(d, kept);
}

ValueRange range_over(const std::vector<Rational>& normal, std::span<const Point> points) {
  ValueRange range{dot(normal, points.front()), dot(normal, points.front())};
  for (const Point& p : points) {
    const Rational value = dot(normal, p);
    if (value < range.low) range.low = value;
    if (value > range.high) range.high = value;
  }
  return range;
}

// The nearest multiple of 2^-k to `value`, for the smallest k >= 0 that brings it within
// `tolerance` (> 0): a point with short numbers. Every later computation from it (the rows'
// boxes, the cuts through it and, through them, the next cells and their points) is
// exact, so its length compounds down the tree; a centre found by LP carries the
// bounding box's widths in its denominators, and cuts through such centres made the
// numbers of deep cells hundreds of digits long.
Rational shortest_dyadic_near(const Rational& value, const Rational& tolerance) {
  mpz_class scale = 1;  // 2^k
  for (;;) {
    const Rational scaled = value * scale;
    mpz_class nearest = scaled.get_num() * 2 + scaled.get_den();  // floor(scaled + 1/2) ...
    mpz_class twice_den = scaled.get_den() * 2;
    mpz_fdiv_q(nearest.get_mpz_t(), nearest.get_mpz_t(), twice_den.get_mpz_t());  // ... exact
    Rational candidate(nearest, scale);
    candidate.canonicalize();
    if (abs(candidate - value) <= tolerance) return candidate;
    scale *= 2;
  }
}

}  // namespace

bool is_axis_aligned(const Polytope& polytope) {
  return std::all_of(polytope.constraints().begin(), polytope.constraints().end(),
                     [](const HalfSpace& h) {
                       return std::count_if(h.normal.begin(), h.normal.end(),
                                            [](const Rational& a) { return sgn(a) != 0; }) == 1;
                     });
}

Point representative_point(const Polytope& polytope, std::span<const Point> vertices) {
  const auto box = bounding_box_of(vertices);
  assert(box);
  std::vector<Rational> half_widths(polytope.dimension());
  for (std::size_t j = 0; j < half_widths.size(); ++j)
    half_widths[j] = (box->high[j] - box->low[j]) / 2;
  // A box cell is its bounding box: the largest copy of the box inside it is the box itself,
  // about its centre, with no LP to solve.
  std::optional<InscribedBox> centre;
  if (is_axis_aligned(polytope)) {
    centre = InscribedBox{Point(polytope.dimension()), 1};
    for (std::size_t j = 0; j < half_widths.size(); ++j)
      centre->centre[j] = box->low[j] + half_widths[j];
  } else {
    centre = polytope.chebyshev_centre(half_widths);
  }
  assert(centre && sgn(centre->radius) > 0);
  // The box of half-widths radius * half_widths about the centre lies in the polytope, so a
  // point within a sixteenth of it on every axis is interior and still central. The cells
  // of repeated halving keep their exact centres: each is already the shortest number that
  // near.
  Point point(polytope.dimension());
  for (std::size_t j = 0; j < point.size(); ++j)
    point[j] = shortest_dyadic_near(centre->centre[j], centre->radius * half_widths[j] / 16);
  return point;
}

BspTree::BspTree(const Point& low, const Point& high) : low_(low), high_(high) {
  const Polytope domain = Polytope::box(low, high);
  nodes_.push_back({});
  nodes_[0].cell = 0;
  cells_.push_back(make_cell(domain, domain.vertices(), 0));
}

BspCell BspTree::make_cell(const Polytope& polytope, std::vector<Point> vertices,
                           std::uint32_t leaf) const {
  BspCell cell;
  cell.polytope = facets_only(polytope, vertices);
  cell.volume = cell.polytope.volume(&vertices);
  cell.representative = representative_point(cell.polytope, vertices);
  cell.vertices = std::move(vertices);
  cell.leaf = leaf;
  return cell;
}

bool BspTree::split(std::size_t cell, const HalfSpace& half_space) {
  const BspCell& parent = cells_[cell];
  // The hyperplane cuts the interior exactly when vertices lie strictly on both sides.
  const ValueRange range = range_over(half_space.normal, parent.vertices);
  if (range.high <= half_space.bound || range.low >= half_space.bound) return false;

  const Polytope below = parent.polytope.intersection(half_space);
  const Polytope above = parent.polytope.intersection(opposite(half_space));
  const auto leaf = parent.leaf;
  const auto below_leaf = static_cast<std::uint32_t>(nodes_.size());
  const auto above_leaf = below_leaf + 1;
  const auto above_cell = static_cast<std::uint32_t>(cells_.size());
  BspCell below_cell = make_cell(below, below.vertices(), below_leaf);
  BspCell above_part = make_cell(above, above.vertices(), above_leaf);

  nodes_[leaf] = BspNode{normalized(half_space), below_leaf, above_leaf, BspNode::kNone};
  nodes_.push_back(BspNode{{}, BspNode::kNone, BspNode::kNone, static_cast<std::uint32_t>(cell)});
  nodes_.push_back(BspNode{{}, BspNode::kNone, BspNode::kNone, above_cell});
  cells_[cell] = std::move(below_cell);
  cells_.push_back(std::move(above_part));
  return true;
}

std::optional<std::size_t> BspTree::locate(const Point& point) const {
  for (std::size_t i = 0; i < dimension(); ++i)
    if (point[i] < low_[i] || point[i] > high_[i]) return std::nullopt;
  std::uint32_t node = 0;
  while (!nodes_[node].is_leaf()) {
    const BspNode& n = nodes_[node];
    node = dot(n.split.normal, point) <= n.split.bound ? n.below : n.above;
  }
  return nodes_[node].cell;
}

std::vector<std::uint32_t> BspTree::cells_meeting(
    const std::function<ValueRange(const std::vector<Rational>&)>& range,
    std::vector<std::uint32_t>* cut_nodes) const {
  std::vector<std::uint32_t> found;
  std::vector<std::uint32_t> pending{0};
  while (!pending.empty()) {
    const BspNode& node = nodes_[pending.back()];
    const std::uint32_t index = pending.back();
    pending.pop_back();
    if (node.is_leaf()) {
      found.push_back(node.cell);
      continue;
    }
    const ValueRange values = range(node.split.normal);
    if (values.high <= node.split.bound) {
      pending.push_back(node.below);
    } else if (values.low >= node.split.bound) {
      pending.push_back(node.above);
    } else {
      pending.push_back(node.below);
      pending.push_back(node.above);
      if (cut_nodes) cut_nodes->push_back(index);
    }
  }
  std::sort(found.begin(), found.end());
  return found;
}

std::vector<RoundedBspNode> BspTree::rounded_nodes() const {
  std::vector<RoundedBspNode> rounded;
  rounded.reserve(nodes_.size());
  for (const BspNode& node : nodes_) {
    RoundedBspNode r;
    for (const Rational& c : node.split.normal)
      r.normal.push_back(to_double(c));
    r.bound = node.is_leaf() ? 0 : to_double(node.split.bound);
    r.below = node.below;
    r.above = node.above;
    r.cell = node.cell;
    rounded.push_back(std::move(r));
  }
  return rounded;
}

std::optional<std::size_t> locate_rounded(std::span<const RoundedBspNode> nodes,
                                          std::span<const double> low, std::span<const double> high,
                                          std::span<const double> point) {
  for (std::size_t i = 0; i < point.size(); ++i)
    if (!(point[i] >= low[i] && point[i] <= high[i])) return std::nullopt;  // NaN: outside
  std::uint32_t node = 0;
  while (nodes[node].cell == BspNode::kNone) {
    const RoundedBspNode& n = nodes[node];
    double value = 0;
    for (std::size_t i = 0; i < point.size(); ++i)
      value += n.normal[i] * point[i];
    node = value <= n.bound ? n.below : n.above;
  }
  return nodes[node].cell;
}

}  // namespace oasis::geom
