#pragma once
// An exact H-polytope {x in R^d : A x <= b} over rationals, d >= 1, and the operations the
// polytope path of the geometry layer needs: membership, intersection, emptiness and
// full-dimensionality, redundancy removal, a Chebyshev centre, affine pre-images, slices,
// vertices, exact volume and a bounding box. Everything is exact (GMP rationals; the linear
// programs run on CGAL's exact simplex through geom/exact_lp.hpp, the only file that
// includes CGAL).
//
// Costs: the linear-programming operations solve one LP (redundancy removal one per
// constraint); vertices() tries every d-subset of the m constraints (C(m, d) small exact
// solves), so it is meant for d <= 4 and a few dozen constraints, which is what partition
// cells have once redundant constraints are gone; volume() runs Lasserre's recursion over the
// facets found from those vertices.

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "geom/half_space.hpp"

namespace oasis::geom {

// A ball of the polytope: every point y with |y_j - centre_j| <= radius * scale_j for all j
// lies in the polytope (a box of half-widths radius * scale; scale 1 gives the max-norm
// Chebyshev ball, exact in rationals unlike the Euclidean one).
struct InscribedBox {
  Point centre;
  Rational radius;
};

struct BoundingBox {
  Point low;
  Point high;
};

class Polytope {
 public:
  // The whole space R^dimension (no constraint).
  explicit Polytope(std::size_t dimension = 0);
  Polytope(std::size_t dimension, std::span<const HalfSpace> constraints);
  // Π [low_i, high_i].
  static Polytope box(const Point& low, const Point& high);

  [[nodiscard]] std::size_t dimension() const { return dimension_; }
  // Normalised (first non-zero coefficient ±1) and without exact repeats; a repeated
  // normal keeps only its tightest bound.
  [[nodiscard]] const std::vector<HalfSpace>& constraints() const { return constraints_; }

  // Adds a constraint in place (normalised; an always-true constant constraint is dropped).
  void add(const HalfSpace& half_space);
  [[nodiscard]] Polytope intersection(const HalfSpace& half_space) const;
  [[nodiscard]] Polytope intersection(const Polytope& other) const;

  // Every constraint holds at `point` (closed: boundary points are contained).
  [[nodiscard]] bool contains(const Point& point) const;
  // Exact LP: no point satisfies every constraint.
  [[nodiscard]] bool is_empty() const;
  // Exact LP: some point satisfies every constraint strictly (non-empty interior).
  [[nodiscard]] bool is_full_dimensional() const;
  // The same set without the constraints the others imply (one exact LP each). An empty
  // polytope comes back as the single constraint 0 <= -1.
  [[nodiscard]] Polytope without_redundancy() const;

  // The centre and radius of the largest box of shape `scale` (all ones when empty) inside
  // the polytope, by exact LP: maximise r subject to a·x + r Σ_j |a_j| scale_j <= b.
  // nullopt when the polytope is empty or unbounded. The radius is 0 for a polytope that is
  // not full-dimensional.
  [[nodiscard]] std::optional<InscribedBox> chebyshev_centre(
      std::span<const Rational> scale = {}) const;

  // {x : M x + t in this polytope} for x' = M x + t with M of size dimension() x n; the
  // result lives in R^n.
  [[nodiscard]] Polytope preimage(const std::vector<std::vector<Rational>>& matrix,
                                  const std::vector<Rational>& offset) const;
  // The polytope with coordinate j fixed to fixed[j] wherever fixed[j] is set, as a polytope
  // over the remaining coordinates (in order). Fixing every coordinate gives a 0-dimensional
  // polytope holding only constant constraints.
  [[nodiscard]] Polytope slice(const std::vector<std::optional<Rational>>& fixed) const;

  // The vertices, exact, sorted and distinct. Meant for bounded polytopes (an unbounded one
  // gets the vertices of its pointed part, if any).
  [[nodiscard]] std::vector<Point> vertices() const;
  // The exact d-dimensional volume of a bounded polytope (0 when it is empty or not
  // full-dimensional); `vertices` may pass the result of vertices() to save recomputing it.
  [[nodiscard]] Rational volume(const std::vector<Point>* vertices = nullptr) const;
  // The smallest box holding the polytope, by 2d exact LPs; nullopt when empty or unbounded.
  [[nodiscard]] std::optional<BoundingBox> bounding_box() const;

 private:
  std::size_t dimension_;
  std::vector<HalfSpace> constraints_;
};

// The box spanned by a set of points (nullopt when the set is empty).
std::optional<BoundingBox> bounding_box_of(std::span<const Point> points);

}  // namespace oasis::geom
