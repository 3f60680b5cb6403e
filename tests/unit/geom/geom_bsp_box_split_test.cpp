// Boxes split down a BSP tree (geom/bsp_box_split.hpp): every piece's measure is checked
// against the general path, the exact volume of the box intersected with the cell's slice
// (Polytope::volume: vertex enumeration and Lasserre's recursion), for boxes inside, across
// and beyond the domain, with and without the floating-point filter, with and without the
// walk by subtrees' boxes (geom/bsp_subtrees.hpp), in one and two free dimensions.

#include <algorithm>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "geom/bsp_box_split.hpp"

namespace oasis {
namespace {

using geom::BspTree;
using geom::CellMeasure;
using geom::HalfSpace;
using geom::Point;
using geom::Polytope;

Rational q(long numerator, long denominator = 1) {
  return Rational(numerator, denominator);
}

// [0, 2]^2 cut by axis-parallel and oblique lines with awkward coefficients, so that pieces
// have crossings with long denominators and boundaries meet box corners.
BspTree sample_tree() {
  BspTree tree({q(0), q(0)}, {q(2), q(2)});
  const std::vector<HalfSpace> cuts{{{q(1), q(1)}, q(1)},           {{q(1), q(0)}, q(3, 2)},
                                    {{q(4, 5), q(-3, 5)}, q(1, 7)}, {{q(0), q(1)}, q(2, 3)},
                                    {{q(-3), q(7)}, q(5, 11)},      {{q(1), q(2)}, q(13, 4)},
                                    {{q(5), q(-1)}, q(3)},          {{q(1), q(-1)}, q(0)}};
  for (const HalfSpace& h : cuts)
    for (std::size_t cell = tree.num_cells(); cell-- > 0;)
      tree.split(cell, h);
  return tree;
}

// vol(box ∩ slice of every cell) by the general path, one exact volume per cell.
std::vector<CellMeasure> general_path(const BspTree& tree,
                                      const std::vector<std::optional<Rational>>& fixed,
                                      const Point& low, const Point& high) {
  std::vector<CellMeasure> found;
  for (std::uint32_t cell = 0; cell < tree.num_cells(); ++cell) {
    const Polytope piece =
        tree.cells()[cell].polytope.slice(fixed).intersection(Polytope::box(low, high));
    const Rational measure = piece.volume();
    if (sgn(measure) > 0) found.push_back({cell, measure});
  }
  return found;
}

void expect_same(const std::vector<CellMeasure>& got, const std::vector<CellMeasure>& want) {
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < got.size(); ++i) {
    EXPECT_EQ(got[i].cell, want[i].cell);
    EXPECT_EQ(got[i].measure, want[i].measure) << "cell " << got[i].cell;
  }
}

Rational random_coordinate(std::mt19937& random) {
  // Multiples of 1/97 in [-1/2, 5/2]: inside, across and beyond the domain [0, 2].
  return q(static_cast<long>(random() % 292) - 48, 97);
}

TEST(BspBoxSplit, SquaresMatchTheGeneralPathWithAndWithoutTheFilter) {
  const BspTree tree = sample_tree();
  ASSERT_GT(tree.num_cells(), 20u);
  const auto rounded = tree.rounded_nodes();
  const geom::BspSubtrees subtrees(tree);
  const std::vector<std::optional<Rational>> fixed(2);
  std::mt19937 random(41);
  for (int trial = 0; trial < 60; ++trial) {
    const Point low{random_coordinate(random), random_coordinate(random)};
    const Point high{low[0] + q(1 + static_cast<long>(random() % 120), 97), low[1] + q(1)};
    const auto want = general_path(tree, fixed, low, high);
    const auto exact = geom::box_cell_measures(tree, fixed, low, high);
    const auto filtered = geom::box_cell_measures(tree, fixed, low, high, rounded);
    const auto by_boxes = geom::box_cell_measures(tree, fixed, low, high, {}, &subtrees);
    ASSERT_TRUE(exact && filtered && by_boxes);
    expect_same(*exact, want);
    expect_same(*filtered, want);
    expect_same(*by_boxes, want);
    // The pieces sum to the box's area inside the domain.
    Rational sum = 0;
    for (const CellMeasure& piece : *exact)
      sum += piece.measure;
    Rational inside = 1;
    for (std::size_t k = 0; k < 2; ++k)
      inside *= std::max(q(0), Rational(std::min(high[k], q(2)) - std::max(low[k], q(0))));
    EXPECT_EQ(sum, inside);
  }
}

TEST(BspBoxSplit, IntervalsOnASliceMatchTheGeneralPath) {
  const BspTree tree = sample_tree();
  std::mt19937 random(7);
  for (int trial = 0; trial < 40; ++trial) {
    const std::size_t free_axis = trial % 2;
    std::vector<std::optional<Rational>> fixed(2);
    fixed[1 - free_axis] = q(static_cast<long>(random() % 195), 97);  // in [0, 2]
    const Point low{random_coordinate(random)};
    const Point high{low[0] + q(1, 2)};
    const auto got = geom::box_cell_measures(tree, fixed, low, high);
    ASSERT_TRUE(got);
    expect_same(*got, general_path(tree, fixed, low, high));
  }
}

TEST(BspBoxSplit, SubtreesInsideTheBoxAreNamedOnceAndNotDescended) {
  const BspTree tree = sample_tree();
  const geom::BspSubtrees subtrees(tree);
  // The whole domain: the root is the one subtree, and nothing is cut.
  const auto all = geom::split_box(tree, {std::nullopt, std::nullopt}, {q(-1), q(-1)}, {q(3), q(3)},
                                   {}, &subtrees);
  ASSERT_TRUE(all);
  EXPECT_EQ(all->whole_subtrees, std::vector<std::uint32_t>{0});
  EXPECT_TRUE(all->cut.empty());
  EXPECT_EQ(all->inside, q(4));
  EXPECT_EQ(subtrees.cells(0).size(), tree.num_cells());
  // A box across the domain: every cell is found once, whole or cut, never both.
  const auto some = geom::split_box(tree, {std::nullopt, std::nullopt}, {q(1, 3), q(-1, 2)},
                                    {q(9, 4), q(5, 3)}, {}, &subtrees);
  ASSERT_TRUE(some);
  std::vector<std::uint32_t> seen;
  for (const std::uint32_t node : some->whole_subtrees)
    for (const std::uint32_t cell : subtrees.cells(node))
      seen.push_back(cell);
  EXPECT_FALSE(seen.empty());
  for (const CellMeasure& piece : some->cut)
    seen.push_back(piece.cell);
  std::sort(seen.begin(), seen.end());
  EXPECT_EQ(std::adjacent_find(seen.begin(), seen.end()), seen.end());
}

TEST(BspBoxSplit, IntervalsOfAOneAxisTreeMatchTheGeneralPathByBoxes) {
  BspTree tree({q(0)}, {q(2)});
  for (const Rational& cut : {q(1, 3), q(5, 4), q(2, 7), q(3, 2), q(1)})
    for (std::size_t cell = tree.num_cells(); cell-- > 0;)
      tree.split(cell, HalfSpace{{q(1)}, cut});
  const geom::BspSubtrees subtrees(tree);
  std::mt19937 random(3);
  for (int trial = 0; trial < 30; ++trial) {
    const Point low{random_coordinate(random)};
    const Point high{low[0] + q(1 + static_cast<long>(random() % 150), 97)};
    const auto got = geom::box_cell_measures(tree, {std::nullopt}, low, high, {}, &subtrees);
    ASSERT_TRUE(got);
    expect_same(*got, general_path(tree, {std::nullopt}, low, high));
  }
}

TEST(BspBoxSplit, OtherDimensionsAreLeftToTheGeneralPath) {
  const BspTree tree = sample_tree();
  EXPECT_FALSE(geom::box_cell_measures(tree, {q(1), q(1)}, {}, {}));
}

}  // namespace
}  // namespace oasis
