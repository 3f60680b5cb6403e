#include "geom/polytope_error_bound.hpp"

#include <algorithm>

namespace oasis::geom {

void add_disturbance(const AffineStep& step, const std::vector<Rational>& normal,
                     ValueRange& range) {
  for (std::size_t i = 0; i < normal.size(); ++i) {
    if (!step.disturbance[i] || sgn(normal[i]) == 0) continue;
    const Rational a = normal[i] * step.disturbance[i]->low;
    const Rational b = normal[i] * step.disturbance[i]->high;
    range.low += std::min(a, b);
    range.high += std::max(a, b);
  }
}
namespace {

Point apply(const AffineStep& step, const Point& x) {
  Point image = step.offset;
  for (std::size_t i = 0; i < image.size(); ++i)
    image[i] += dot(step.matrix[i], x);
  return image;
}

// {x : a · (M x + t) <= c}: the pre-image of a half-space that reads undisturbed axes only.
HalfSpace preimage_of(const AffineStep& step, const HalfSpace& target) {
  const std::size_t n = step.offset.size();
  HalfSpace result{std::vector<Rational>(n, 0), target.bound - dot(target.normal, step.offset)};
  for (std::size_t i = 0; i < n; ++i) {
    if (sgn(target.normal[i]) == 0) continue;
    for (std::size_t j = 0; j < n; ++j)
      result.normal[j] += target.normal[i] * step.matrix[i][j];
  }
  return result;
}

HalfSpace axis_half_space(std::size_t n, std::size_t axis, int sign, const Rational& bound) {
  HalfSpace h{std::vector<Rational>(n, 0), bound};
  h.normal[axis] = sign;
  return h;
}

// The domain on the undisturbed axes. The images may be inside (nothing set), outside on one
// axis (`outside`), or straddle an edge (`straddled`: that edge as a half-space). Images
// that only touch an edge from outside count as outside: the points of the cell that map
// onto the edge form a set of measure zero (docs/geometry.md, "The polytope path").
struct DomainVerdict {
  bool outside = false;
  std::optional<HalfSpace> straddled;
};

DomainVerdict undisturbed_domain(const PolytopeGeometry& geometry, const AffineStep& step,
                                 const std::vector<Point>& images) {
  const std::size_t n = geometry.dimension();
  DomainVerdict verdict;
  for (std::size_t i = 0; i < n; ++i) {
    if (step.disturbance[i]) continue;
    const auto [low_image, high_image] = std::minmax_element(
        images.begin(), images.end(), [i](const Point& a, const Point& b) { return a[i] < b[i]; });
    const Rational& low = (*low_image)[i];
    const Rational& high = (*high_image)[i];
    const Rational& edge_low = geometry.domain_low[i];
    const Rational& edge_high = geometry.domain_high[i];
    const bool below = high < edge_low || (high == edge_low && low < edge_low);
    const bool above = low > edge_high || (low == edge_high && high > edge_high);
    if (below || above) {
      verdict.outside = true;
      return verdict;
    }
    if (!verdict.straddled && low < edge_high && edge_high < high)
      verdict.straddled = axis_half_space(n, i, 1, edge_high);
    if (!verdict.straddled && low < edge_low && edge_low < high)
      verdict.straddled = axis_half_space(n, i, -1, -edge_low);
  }
  return verdict;
}

// Σ_{i in D} |δ_i| / w_i, the shift's cost against the disturbance box.
Rational shift_cost(const AffineStep& step, const Point& from, const Point& to) {
  Rational total = 0;
  for (std::size_t i = 0; i < from.size(); ++i)
    if (step.disturbance[i]) total += abs(to[i] - from[i]) / step.disturbance[i]->width();
  return total;
}

}  // namespace

CellErrorBound cell_error_bound(const PolytopeGeometry& geometry, const BspTree& tree,
                                std::size_t cell, std::size_t action) {
  const AffineStep& step = geometry.actions[action];
  const BspCell& c = tree.cells()[cell];
  std::vector<Point> images;
  for (const Point& v : c.vertices)
    images.push_back(apply(step, v));
  CellErrorBound bound;
  if (step.has_undisturbed_axis()) {
    const DomainVerdict domain = undisturbed_domain(geometry, step, images);
    if (domain.outside) return bound;  // every successor leaves the domain: exact
    if (domain.straddled) {
      bound.epsilon = 1;
      bound.preimage_split = preimage_of(step, *domain.straddled);
      return bound;
    }
    // The range of a·z over S_C = conv(images) + W.
    auto range = [&](const std::vector<Rational>& normal) {
      ValueRange r{dot(normal, images.front()), dot(normal, images.front())};
      for (const Point& p : images) {
        const Rational value = dot(normal, p);
        if (value < r.low) r.low = value;
        if (value > r.high) r.high = value;
      }
      add_disturbance(step, normal, r);
      return r;
    };
    std::vector<std::uint32_t> cut;
    (void)tree.cells_meeting(range, &cut);
    for (const std::uint32_t node : cut) {
      const HalfSpace& h = tree.nodes()[node].split;
      bool reads_undisturbed = false;
      bool reads_disturbed = false;
      for (std::size_t i = 0; i < h.normal.size(); ++i) {
        if (sgn(h.normal[i]) == 0) continue;
        (step.disturbance[i] ? reads_disturbed : reads_undisturbed) = true;
      }
      if (!reads_undisturbed) continue;
      bound.epsilon = 1;
      if (!reads_disturbed) bound.preimage_split = preimage_of(step, h);
      return bound;
    }
  }
  const Point centre_image = apply(step, c.representative);
  for (const Point& image : images)
    bound.epsilon = std::max(bound.epsilon, shift_cost(step, centre_image, image));
  if (bound.epsilon > 1) bound.epsilon = 1;
  return bound;
}

Rational partition_error_bound(const PolytopeGeometry& geometry, const BspTree& tree) {
  Rational worst = 0;
  for (std::size_t cell = 0; cell < tree.num_cells(); ++cell)
    for (std::size_t a = 0; a < geometry.actions.size(); ++a)
      worst = std::max(worst, cell_error_bound(geometry, tree, cell, a).epsilon);
  return worst;
}

}  // namespace oasis::geom
