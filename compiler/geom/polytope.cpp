#include "geom/polytope.hpp"

#include <algorithm>
#include <cassert>

#include "geom/exact_lp.hpp"

namespace oasis::geom {
namespace {

// Solves the square system rows · x = rhs exactly by Gaussian elimination; nullopt when it
// is singular.
std::optional<Point> solve_square(std::vector<std::vector<Rational>> rows, Point rhs) {
  const std::size_t n = rows.size();
  for (std::size_t column = 0; column < n; ++column) {
    std::size_t pivot = column;
    while (pivot < n && sgn(rows[pivot][column]) == 0)
      ++pivot;
    if (pivot == n) return std::nullopt;
    std::swap(rows[pivot], rows[column]);
    std::swap(rhs[pivot], rhs[column]);
    for (std::size_t r = 0; r < n; ++r) {
      if (r == column || sgn(rows[r][column]) == 0) continue;
      const Rational factor = rows[r][column] / rows[column][column];
      for (std::size_t c = column; c < n; ++c)
        rows[r][c] -= factor * rows[column][c];
      rhs[r] -= factor * rhs[column];
    }
  }
  Point x(n);
  for (std::size_t i = 0; i < n; ++i)
    x[i] = rhs[i] / rows[i][i];
  return x;
}

bool satisfies_all(std::span<const HalfSpace> constraints, const Point& point) {
  return std::all_of(constraints.begin(), constraints.end(),
                     [&](const HalfSpace& h) { return dot(h.normal, point) <= h.bound; });
}

// Every vertex of {x in R^k : constraints}: the feasible solutions of every k-subset of the
// constraints taken as equalities.
std::vector<Point> enumerate_vertices(std::span<const HalfSpace> constraints, std::size_t k) {
  std::vector<Point> found;
  const std::size_t m = constraints.size();
  if (k == 0 || m < k) return found;
  std::vector<std::size_t> subset(k);
  for (std::size_t i = 0; i < k; ++i)
    subset[i] = i;
  for (;;) {
    std::vector<std::vector<Rational>> rows;
    Point rhs;
    for (const std::size_t i : subset) {
      rows.push_back(constraints[i].normal);
      rhs.push_back(constraints[i].bound);
    }
    if (auto point = solve_square(std::move(rows), std::move(rhs));
        point && satisfies_all(constraints, *point))
      found.push_back(std::move(*point));
    // Next k-subset in lexicographic order.
    std::size_t i = k;
    while (i > 0 && subset[i - 1] == m - k + (i - 1))
      --i;
    if (i == 0) break;
    ++subset[i - 1];
    for (std::size_t j = i; j < k; ++j)
      subset[j] = subset[j - 1] + 1;
  }
  std::sort(found.begin(), found.end());
  found.erase(std::unique(found.begin(), found.end()), found.end());
  return found;
}

// Drops exact repeats of a hyperplane (after normalisation), which would count a facet twice.
std::vector<HalfSpace> distinct(std::vector<HalfSpace> constraints) {
  for (HalfSpace& h : constraints)
    h = normalized(h);
  std::sort(constraints.begin(), constraints.end(), [](const HalfSpace& a, const HalfSpace& b) {
    return a.normal != b.normal ? a.normal < b.normal : a.bound < b.bound;
  });
  constraints.erase(std::unique(constraints.begin(), constraints.end()), constraints.end());
  return constraints;
}

// Lasserre's recursion: vol_k(P) = (1/k) Σ_i h_i vol_{k-1}(F_i), h_i the signed distance of
// facet F_i from an origin. Measuring each facet through its projection along a coordinate
// q with a_iq != 0 removes every square root: h_i vol(F_i) = (b_i - a_i·o) / |a_iq| ·
// vol(proj_q F_i). The origin o is a vertex, so the facets through it drop out; facets are
// recognised as the constraints that at least k vertices make tight.
Rational lasserre_volume(const std::vector<HalfSpace>& given, const std::vector<Point>& vertices,
                         std::size_t k) {
  if (vertices.size() < k + 1) return 0;
  if (k == 1) {
    const auto [low, high] = std::minmax_element(vertices.begin(), vertices.end());
    return (*high)[0] - (*low)[0];
  }
  const std::vector<HalfSpace> constraints = distinct(given);
  const Point& origin = vertices.front();
  Rational total = 0;
  for (const HalfSpace& facet : constraints) {
    if (is_constant(facet)) continue;
    const Rational height = facet.bound - dot(facet.normal, origin);
    if (sgn(height) == 0) continue;
    std::vector<const Point*> tight;
    for (const Point& v : vertices)
      if (dot(facet.normal, v) == facet.bound) tight.push_back(&v);
    if (tight.size() < k) continue;
    // Project along the coordinate with the largest coefficient (any non-zero one works).
    std::size_t q = 0;
    for (std::size_t j = 1; j < k; ++j)
      if (abs(facet.normal[j]) > abs(facet.normal[q])) q = j;
    auto drop_q = [&](const Point& p) {
      Point result;
      for (std::size_t j = 0; j < k; ++j)
        if (j != q) result.push_back(p[j]);
      return result;
    };
    std::vector<Point> facet_vertices;
    for (const Point* v : tight)
      facet_vertices.push_back(drop_q(*v));
    // On the facet x_q = (b - Σ_{j != q} a_j x_j) / a_q: substitute into the other rows.
    std::vector<HalfSpace> facet_constraints;
    for (const HalfSpace& other : constraints) {
      if (&other == &facet || sgn(other.normal[q]) == 0) {
        if (&other != &facet && !is_constant(other))
          facet_constraints.push_back({drop_q(other.normal), other.bound});
        continue;
      }
      const Rational ratio = other.normal[q] / facet.normal[q];
      HalfSpace row{drop_q(other.normal), other.bound - ratio * facet.bound};
      std::size_t column = 0;
      for (std::size_t j = 0; j < k; ++j)
        if (j != q) row.normal[column++] -= ratio * facet.normal[j];
      if (!is_constant(row)) facet_constraints.push_back(std::move(row));
    }
    total +=
        height / abs(facet.normal[q]) * lasserre_volume(facet_constraints, facet_vertices, k - 1);
  }
  return total / static_cast<long>(k);
}

}  // namespace

Polytope::Polytope(std::size_t dimension) : dimension_(dimension) {}

Polytope::Polytope(std::size_t dimension, std::span<const HalfSpace> constraints)
    : dimension_(dimension) {
  for (const HalfSpace& h : constraints)
    add(h);
}

Polytope Polytope::box(const Point& low, const Point& high) {
  Polytope result(low.size());
  for (std::size_t i = 0; i < low.size(); ++i) {
    std::vector<Rational> normal(low.size(), 0);
    normal[i] = 1;
    result.add({normal, high[i]});
    normal[i] = -1;
    result.add({normal, -low[i]});
  }
  return result;
}

void Polytope::add(const HalfSpace& half_space) {
  assert(half_space.normal.size() == dimension_);
  HalfSpace h = normalized(half_space);
  if (is_constant(h) && sgn(h.bound) >= 0) return;  // always true
  for (HalfSpace& existing : constraints_) {
    if (existing.normal == h.normal) {
      if (h.bound < existing.bound) existing.bound = h.bound;
      return;
    }
  }
  constraints_.push_back(std::move(h));
}

Polytope Polytope::intersection(const HalfSpace& half_space) const {
  Polytope result = *this;
  result.add(half_space);
  return result;
}

Polytope Polytope::intersection(const Polytope& other) const {
  Polytope result = *this;
  for (const HalfSpace& h : other.constraints_)
    result.add(h);
  return result;
}

bool Polytope::contains(const Point& point) const {
  return satisfies_all(constraints_, point);
}

bool Polytope::is_empty() const {
  const std::vector<Rational> zero(dimension_, 0);
  return maximize(constraints_, zero).status == LpStatus::Infeasible;
}

bool Polytope::is_full_dimensional() const {
  // maximise s subject to a·x + s <= b and s <= 1: positive exactly when some point is
  // strictly inside every constraint.
  std::vector<HalfSpace> rows;
  for (const HalfSpace& h : constraints_) {
    HalfSpace row = h;
    row.normal.push_back(1);
    rows.push_back(std::move(row));
  }
  std::vector<Rational> slack(dimension_ + 1, 0);
  slack.back() = 1;
  rows.push_back({slack, 1});
  const LpSolution solution = maximize(rows, slack);
  return solution.status == LpStatus::Optimal && sgn(solution.value) > 0;
}

Polytope Polytope::without_redundancy() const {
  if (is_empty()) {
    Polytope empty(dimension_);
    empty.constraints_.push_back({std::vector<Rational>(dimension_, 0), -1});
    return empty;
  }
  // Constraint i is redundant when the others bound a·x by b_i already; dropping the
  // redundant ones as they are found keeps the rest an equivalent system.
  std::vector<HalfSpace> kept = constraints_;
  for (std::size_t i = kept.size(); i-- > 0;) {
    const HalfSpace candidate = kept[i];
    kept.erase(kept.begin() + static_cast<std::ptrdiff_t>(i));
    const LpSolution best = maximize(kept, candidate.normal);
    if (best.status == LpStatus::Optimal && best.value <= candidate.bound) continue;
    kept.insert(kept.begin() + static_cast<std::ptrdiff_t>(i), candidate);
  }
  Polytope result(dimension_);
  result.constraints_ = std::move(kept);
  return result;
}

std::optional<InscribedBox> Polytope::chebyshev_centre(std::span<const Rational> scale) const {
  std::vector<HalfSpace> rows;
  for (const HalfSpace& h : constraints_) {
    HalfSpace row = h;
    Rational reach = 0;
    for (std::size_t j = 0; j < dimension_; ++j)
      reach += abs(h.normal[j]) * (scale.empty() ? Rational(1) : scale[j]);
    row.normal.push_back(reach);
    rows.push_back(std::move(row));
  }
  std::vector<Rational> objective(dimension_ + 1, 0);
  objective.back() = 1;
  const LpSolution solution = maximize(rows, objective);
  if (solution.status != LpStatus::Optimal || sgn(solution.value) < 0) return std::nullopt;
  InscribedBox ball;
  ball.centre.assign(solution.point.begin(), solution.point.end() - 1);
  ball.radius = solution.value;
  return ball;
}

Polytope Polytope::preimage(const std::vector<std::vector<Rational>>& matrix,
                            const std::vector<Rational>& offset) const {
  const std::size_t n = matrix.empty() ? 0 : matrix.front().size();
  Polytope result(n);
  for (const HalfSpace& h : constraints_) {
    // a · (M x + t) <= b  ⟺  (aᵀ M) x <= b - a · t.
    HalfSpace row{std::vector<Rational>(n, 0), h.bound - dot(h.normal, offset)};
    for (std::size_t i = 0; i < dimension_; ++i) {
      if (sgn(h.normal[i]) == 0) continue;
      for (std::size_t j = 0; j < n; ++j)
        row.normal[j] += h.normal[i] * matrix[i][j];
    }
    result.add(row);
  }
  return result;
}

Polytope Polytope::slice(const std::vector<std::optional<Rational>>& fixed) const {
  std::size_t free = 0;
  for (const auto& value : fixed)
    free += value ? 0 : 1;
  Polytope result(free);
  for (const HalfSpace& h : constraints_) {
    HalfSpace row{{}, h.bound};
    for (std::size_t j = 0; j < dimension_; ++j) {
      if (fixed[j]) {
        row.bound -= h.normal[j] * *fixed[j];
      } else {
        row.normal.push_back(h.normal[j]);
      }
    }
    result.add(row);
  }
  return result;
}

std::vector<Point> Polytope::vertices() const {
  return enumerate_vertices(constraints_, dimension_);
}

Rational Polytope::volume(const std::vector<Point>* known_vertices) const {
  if (known_vertices) return lasserre_volume(constraints_, *known_vertices, dimension_);
  return lasserre_volume(constraints_, vertices(), dimension_);
}

std::optional<BoundingBox> Polytope::bounding_box() const {
  BoundingBox box{Point(dimension_), Point(dimension_)};
  for (std::size_t j = 0; j < dimension_; ++j) {
    std::vector<Rational> axis(dimension_, 0);
    axis[j] = 1;
    const LpSolution high = maximize(constraints_, axis);
    if (high.status != LpStatus::Optimal) return std::nullopt;
    axis[j] = -1;
    const LpSolution low = maximize(constraints_, axis);
    if (low.status != LpStatus::Optimal) return std::nullopt;
    box.high[j] = high.value;
    box.low[j] = -low.value;
  }
  return box;
}

std::optional<BoundingBox> bounding_box_of(std::span<const Point> points) {
  if (points.empty()) return std::nullopt;
  BoundingBox box{points.front(), points.front()};
  for (const Point& p : points) {
    for (std::size_t j = 0; j < p.size(); ++j) {
      if (p[j] < box.low[j]) box.low[j] = p[j];
      if (p[j] > box.high[j]) box.high[j] = p[j];
    }
  }
  return box;
}

}  // namespace oasis::geom
