// Exact H-polytopes (geom/polytope.hpp): membership, emptiness, redundancy, Chebyshev
// centres, pre-images, slices, vertices and volumes in one to four dimensions, checked
// against values known in closed form.

#include <gtest/gtest.h>

#include "geom/bsp_tree.hpp"
#include "geom/polytope.hpp"

namespace oasis {
namespace {

using geom::HalfSpace;
using geom::Point;
using geom::Polytope;

Rational q(long numerator, long denominator = 1) {
  return Rational(numerator, denominator);
}

Point point(std::initializer_list<Rational> values) {
  return Point(values);
}

// {x >= 0 in R^d : Σ x_i <= 1}: volume 1/d!.
Polytope standard_simplex(std::size_t d) {
  Polytope simplex(d);
  for (std::size_t i = 0; i < d; ++i) {
    std::vector<Rational> normal(d, 0);
    normal[i] = -1;
    simplex.add({normal, 0});
  }
  simplex.add({std::vector<Rational>(d, 1), 1});
  return simplex;
}

// {x in R^d : Σ |x_i| <= 1}: 2^d constraints, volume 2^d / d!.
Polytope cross_polytope(std::size_t d) {
  Polytope cross(d);
  for (std::size_t signs = 0; signs < (std::size_t{1} << d); ++signs) {
    std::vector<Rational> normal(d);
    for (std::size_t i = 0; i < d; ++i)
      normal[i] = ((signs >> i) & 1) ? -1 : 1;
    cross.add({normal, 1});
  }
  return cross;
}

Polytope unit_cube(std::size_t d) {
  return Polytope::box(Point(d, 0), Point(d, 1));
}

Rational factorial(long n) {
  return n <= 1 ? q(1) : q(n) * factorial(n - 1);
}

TEST(GeomPolytope, IntervalInOneDimension) {
  const Polytope interval = Polytope::box(point({q(1)}), point({q(3)}));
  EXPECT_EQ(interval.volume(), 2);
  EXPECT_EQ(interval.vertices(), (std::vector<Point>{point({q(1)}), point({q(3)})}));
  const auto centre = interval.chebyshev_centre();
  ASSERT_TRUE(centre);
  EXPECT_EQ(centre->centre, point({q(2)}));
  EXPECT_EQ(centre->radius, 1);
  EXPECT_TRUE(interval.contains(point({q(3)})));
  EXPECT_FALSE(interval.contains(point({q(7, 2)})));
}

TEST(GeomPolytope, SimplexVolumesAreOneOverDFactorial) {
  for (std::size_t d = 1; d <= 4; ++d) {
    const Polytope simplex = standard_simplex(d);
    EXPECT_EQ(simplex.vertices().size(), d + 1) << d;
    EXPECT_EQ(simplex.volume(), 1 / factorial(static_cast<long>(d))) << d;
  }
}

TEST(GeomPolytope, CrossPolytopesHaveTwoToTheDOverDFactorial) {
  for (std::size_t d = 1; d <= 4; ++d) {
    const Polytope cross = cross_polytope(d);
    EXPECT_EQ(cross.vertices().size(), 2 * d) << d;  // ±e_i
    EXPECT_EQ(cross.volume(), q(1L << d) / factorial(static_cast<long>(d))) << d;
  }
}

TEST(GeomPolytope, BoxesAndTheirVertices) {
  const Polytope box = Polytope::box(point({0, 0, 0, 0}), point({1, 2, 3, q(1, 2)}));
  EXPECT_EQ(box.volume(), 3);
  EXPECT_EQ(box.vertices().size(), 16U);
  const auto bounds = box.bounding_box();
  ASSERT_TRUE(bounds);
  EXPECT_EQ(bounds->high, point({1, 2, 3, q(1, 2)}));
  EXPECT_EQ(bounds->low, point({0, 0, 0, 0}));
}

// A non-simple vertex: the apex of a square pyramid lies on four facets.
TEST(GeomPolytope, PyramidWithADegenerateApex) {
  Polytope pyramid(3);
  pyramid.add({{0, 0, -1}, 0});  // z >= 0
  pyramid.add({{0, -3, 1}, 0});  // z <= 3y
  pyramid.add({{-3, 0, 1}, 0});  // z <= 3x
  pyramid.add({{0, 3, 1}, 6});   // z <= 3 (2 - y)
  pyramid.add({{3, 0, 1}, 6});   // z <= 3 (2 - x)
  EXPECT_EQ(pyramid.vertices().size(), 5U);
  EXPECT_EQ(pyramid.volume(), 4);  // base 2 x 2, height 3, over 3
}

TEST(GeomPolytope, HalfOfTheHypercubeBySymmetry) {
  Polytope half = unit_cube(4).intersection(HalfSpace{{1, 1, 1, 1}, 2});
  EXPECT_EQ(half.volume(), q(1, 2));
  EXPECT_TRUE(half.is_full_dimensional());
  // A corner cut off: x1 + x2 + x3 + x4 <= 1 leaves the simplex, 1/24.
  EXPECT_EQ(unit_cube(4).intersection(HalfSpace{{1, 1, 1, 1}, 1}).volume(), q(1, 24));
}

TEST(GeomPolytope, EmptinessAndFullDimensionality) {
  Polytope empty(2);
  empty.add({{1, 0}, 0});
  empty.add({{-1, 0}, -1});  // x >= 1 and x <= 0
  EXPECT_TRUE(empty.is_empty());
  EXPECT_FALSE(empty.is_full_dimensional());
  EXPECT_EQ(empty.volume(), 0);

  Polytope flat = Polytope::box(point({0, 0}), point({1, 1}));
  flat.add({{1, -1}, 0});
  flat.add({{-1, 1}, 0});  // the diagonal x = y
  EXPECT_FALSE(flat.is_empty());
  EXPECT_FALSE(flat.is_full_dimensional());
  EXPECT_EQ(flat.volume(), 0);

  Polytope flat_square = unit_cube(3);
  flat_square.add({{0, 0, 1}, 0});  // z <= 0: the bottom face only
  EXPECT_FALSE(flat_square.is_full_dimensional());
  EXPECT_EQ(flat_square.volume(), 0);
  EXPECT_TRUE(standard_simplex(3).is_full_dimensional());
}

TEST(GeomPolytope, RedundantConstraintsAreRemoved) {
  Polytope cube = unit_cube(3);
  cube.add({{1, 1, 1}, 3});
  cube.add({{1, 1, 0}, 5});
  cube.add({{2, 0, 0}, 4});  // x <= 2: the same normal as x <= 1 after normalising
  EXPECT_EQ(cube.constraints().size(), 8U);
  const Polytope clean = cube.without_redundancy();
  EXPECT_EQ(clean.constraints().size(), 6U);
  EXPECT_EQ(clean.volume(), 1);
  const Polytope empty = Polytope::box(point({0}), point({1})).intersection(HalfSpace{{1}, -1});
  EXPECT_EQ(empty.without_redundancy().constraints().size(), 1U);
  EXPECT_TRUE(empty.without_redundancy().is_empty());
}

TEST(GeomPolytope, ChebyshevCentres) {
  const auto triangle = standard_simplex(2).chebyshev_centre();
  ASSERT_TRUE(triangle);  // max-norm ball: x = y = r and x + y + 2r = 1
  EXPECT_EQ(triangle->centre, point({q(1, 4), q(1, 4)}));
  EXPECT_EQ(triangle->radius, q(1, 4));
  // A box scaled by its own half-widths: the centre, radius 1, unique.
  const Polytope box = Polytope::box(point({0, 0, 0}), point({4, 2, 1}));
  const std::vector<Rational> half_widths{2, 1, q(1, 2)};
  const auto centre = box.chebyshev_centre(half_widths);
  ASSERT_TRUE(centre);
  EXPECT_EQ(centre->centre, point({2, 1, q(1, 2)}));
  EXPECT_EQ(centre->radius, 1);
  Polytope unbounded(2);
  unbounded.add({{1, 0}, 0});
  EXPECT_FALSE(unbounded.chebyshev_centre());
  EXPECT_FALSE(unbounded.bounding_box());
}

TEST(GeomPolytope, PreimagesUnderAffineMaps) {
  const Polytope square = unit_cube(2);
  // A quarter turn x' = -y, y' = x: the pre-image of [0,1]^2 is [0,1] x [-1,0].
  const Polytope turned = square.preimage({{0, -1}, {1, 0}}, {0, 0});
  EXPECT_TRUE(turned.contains(point({q(1, 2), q(-1, 2)})));
  EXPECT_FALSE(turned.contains(point({q(1, 2), q(1, 2)})));
  EXPECT_EQ(turned.volume(), 1);
  // x' = 2 x + 1 on the line: the pre-image of [0, 1] is [-1/2, 0].
  const Polytope line = Polytope::box(point({0}), point({1})).preimage({{2}}, {1});
  EXPECT_EQ(line.vertices(), (std::vector<Point>{point({q(-1, 2)}), point({0})}));
  // A projection R^3 -> R^2 (x' = x, y' = y + z): an unbounded slab in z; cut to a box.
  const Polytope slab = square.preimage({{1, 0, 0}, {0, 1, 1}}, {0, 0});
  EXPECT_EQ(slab.intersection(unit_cube(3)).volume(), q(1, 2));
  // A shear in 4-D keeps volumes.
  const Polytope sheared = unit_cube(4).preimage(
      {{1, 1, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, q(1, 3)}, {0, 0, 0, 1}}, {0, 0, 0, 0});
  EXPECT_EQ(sheared.volume(), 1);
}

TEST(GeomPolytope, SlicesAndIntersections) {
  const Polytope triangle = standard_simplex(2);
  const Polytope at_half = triangle.slice({q(1, 2), std::nullopt});
  EXPECT_EQ(at_half.dimension(), 1U);
  EXPECT_EQ(at_half.volume(), q(1, 2));
  const Polytope tetrahedron = standard_simplex(3);
  EXPECT_EQ(tetrahedron.slice({std::nullopt, std::nullopt, q(1, 2)}).volume(), q(1, 8));
  const Polytope cut = triangle.intersection(HalfSpace{{1, 0}, q(1, 2)});
  EXPECT_EQ(cut.volume(), q(3, 8));
  const Polytope diamond = cross_polytope(2);
  const Polytope both = diamond.intersection(unit_cube(2));
  EXPECT_EQ(both.volume(), q(1, 2));
  const auto bounds = diamond.bounding_box();
  ASSERT_TRUE(bounds);
  EXPECT_EQ(bounds->low, point({-1, -1}));
  EXPECT_EQ(bounds->high, point({1, 1}));
}

// Cells are split through their representatives, so the representatives' numbers are
// those of every deeper cell: they must stay short. A triangle's LP centre has the bounding
// box's widths in its denominators; the representative is the shortest dyadic point near it.
TEST(GeomPolytope, RepresentativesStayShortInteriorAndCentral) {
  geom::BspTree tree({q(0), q(0)}, {q(2), q(2)});
  tree.split(0, HalfSpace{{q(1), q(1)}, q(1)});  // the triangle x + y <= 1 and the rest
  for (int round = 0; round < 8; ++round) {
    for (std::size_t cell = tree.num_cells(); cell-- > 0;) {
      const Point& r = tree.cells()[cell].representative;
      tree.split(cell,
                 HalfSpace{{q(round % 2 == 0 ? 1 : 0), q(round % 2 == 0 ? 0 : 1)}, r[round % 2]});
    }
  }
  ASSERT_GT(tree.num_cells(), 200U);
  for (const geom::BspCell& cell : tree.cells()) {
    const Point& r = cell.representative;
    for (const HalfSpace& h : cell.polytope.constraints())
      EXPECT_LT(geom::dot(h.normal, r), h.bound);  // interior
    bool is_box = true;
    for (const HalfSpace& h : cell.polytope.constraints())
      is_box = is_box && (sgn(h.normal[0]) == 0 || sgn(h.normal[1]) == 0);
    for (std::size_t j = 0; j < 2; ++j) {
      const mpz_class& den = r[j].get_den();
      EXPECT_EQ(mpz_popcount(den.get_mpz_t()), 1U) << "a power of two";
      EXPECT_LE(mpz_sizeinbase(den.get_mpz_t(), 2), 24U);
      EXPECT_LE(mpz_sizeinbase(r[j].get_num().get_mpz_t(), 2), 24U);
    }
    if (!is_box) continue;
    const auto box = geom::bounding_box_of(cell.vertices);
    ASSERT_TRUE(box);
    for (std::size_t j = 0; j < 2; ++j)  // within a sixteenth of the half-width of the centre
      EXPECT_LE(abs(r[j] - (box->low[j] + box->high[j]) / 2), (box->high[j] - box->low[j]) / 32);
  }
  // The cells of repeated halving keep their exact centres.
  geom::BspTree halved({q(0), q(-1)}, {q(3), q(1)});
  for (int round = 0; round < 6; ++round) {
    for (std::size_t cell = halved.num_cells(); cell-- > 0;) {
      const Point& r = halved.cells()[cell].representative;
      halved.split(cell, HalfSpace{{q(1 - round % 2), q(round % 2)}, r[round % 2]});
    }
  }
  for (const geom::BspCell& cell : halved.cells()) {
    const auto box = geom::bounding_box_of(cell.vertices);
    ASSERT_TRUE(box);
    for (std::size_t j = 0; j < 2; ++j)
      EXPECT_EQ(cell.representative[j], (box->low[j] + box->high[j]) / 2);
  }
}

}  // namespace
}  // namespace oasis
