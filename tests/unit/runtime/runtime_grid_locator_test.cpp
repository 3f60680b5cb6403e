// Point location in a gridded abstraction (runtime, C++17 only): the boundary rule, the
// outside of the domain, malformed grids, and agreement with a plain linear scan on a
// million random points.

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "oasis/rt/grid_locator.hpp"

namespace {

using oasis::rt::GridView;
using oasis::rt::kOutsideCell;

// A 2-D grid over state coordinates 2 (x) and 0 (y): x in {0, 1, 2.5, 5}, y in {-3, 0, 3}.
struct SmallGrid {
  std::vector<std::uint32_t> axes{2, 0};
  std::vector<std::uint32_t> begin{0, 4, 7};
  std::vector<double> breaks{0, 1, 2.5, 5, -3, 0, 3};
  GridView view() const { return {2, axes.data(), begin.data(), breaks.data()}; }
};

std::uint32_t locate(const GridView& grid, double x, double y) {
  const double state[3] = {y, 123.0, x};  // other coordinates are ignored
  return oasis::rt::locate_cell(grid, state, 3);
}

TEST(GridLocator, CellsAreRowMajorWithTheLastAxisFastest) {
  const SmallGrid grid;
  EXPECT_EQ(oasis::rt::grid_cells(grid.view()), 6U);
  EXPECT_EQ(locate(grid.view(), 0.5, -1), 0U);
  EXPECT_EQ(locate(grid.view(), 0.5, 1), 1U);
  EXPECT_EQ(locate(grid.view(), 2, -1), 2U);
  EXPECT_EQ(locate(grid.view(), 4, 2), 5U);
}

TEST(GridLocator, SharedFacesBelongToTheCellAboveAndTheHighEndToTheLast) {
  const SmallGrid grid;
  EXPECT_EQ(locate(grid.view(), 1, -3), 2U);  // x = 1 opens [1, 2.5)
  EXPECT_EQ(locate(grid.view(), 0, 0), 1U);   // y = 0 opens [0, 3]
  EXPECT_EQ(locate(grid.view(), 5, 3), 5U);   // both high ends: the last cell
  EXPECT_EQ(locate(grid.view(), 0, -3), 0U);  // both low ends: the first cell
}

TEST(GridLocator, OutsideTheDomainOrNotANumberIsOutside) {
  const SmallGrid grid;
  EXPECT_EQ(locate(grid.view(), -0.001, 0), kOutsideCell);
  EXPECT_EQ(locate(grid.view(), 5.001, 0), kOutsideCell);
  EXPECT_EQ(locate(grid.view(), 1, 3.5), kOutsideCell);
  EXPECT_EQ(locate(grid.view(), std::nan(""), 0), kOutsideCell);
  EXPECT_EQ(locate(grid.view(), 1, std::numeric_limits<double>::infinity()), kOutsideCell);
  const double short_state[1] = {0};  // the x axis (index 2) is missing
  EXPECT_EQ(oasis::rt::locate_cell(grid.view(), short_state, 1), kOutsideCell);
}

TEST(GridLocator, ValidateRefusesMalformedGrids) {
  SmallGrid grid;
  EXPECT_TRUE(oasis::rt::validate_grid(grid.view(), 3));
  EXPECT_FALSE(oasis::rt::validate_grid(grid.view(), 2));  // axis 2 past the state
  grid.breaks[2] = 1;                                      // not strictly increasing
  EXPECT_FALSE(oasis::rt::validate_grid(grid.view(), 3));
  grid.breaks[2] = std::nan("");
  EXPECT_FALSE(oasis::rt::validate_grid(grid.view(), 3));
  SmallGrid one_break;
  one_break.begin = {0, 1, 7};  // axis 0 with a single breakpoint
  EXPECT_FALSE(oasis::rt::validate_grid(one_break.view(), 3));
  GridView empty;
  EXPECT_FALSE(oasis::rt::validate_grid(empty, 3));
}

// The reference: a linear scan with the boundary rule written out.
std::uint32_t scan(const std::vector<double>& t, double x) {
  if (!(x >= t.front() && x <= t.back())) return kOutsideCell;
  for (std::uint32_t k = 0; k + 1 < t.size(); ++k)
    if (t[k] <= x && (x < t[k + 1] || k + 2 == t.size())) return k;
  return kOutsideCell;
}

TEST(GridLocator, AgreesWithALinearScanOnAMillionPoints) {
  std::mt19937_64 random(42);
  // Uneven breakpoints, as a compiler grid with reward edges has.
  std::vector<double> xs{0};
  std::vector<double> ys{-3};
  while (xs.back() < 5)
    xs.push_back(xs.back() + std::uniform_real_distribution<double>(0.01, 0.1)(random));
  while (ys.back() < 3)
    ys.push_back(ys.back() + std::uniform_real_distribution<double>(0.01, 0.1)(random));
  std::vector<double> breaks = xs;
  breaks.insert(breaks.end(), ys.begin(), ys.end());
  const std::vector<std::uint32_t> axes{0, 1};
  const std::vector<std::uint32_t> begin{0, static_cast<std::uint32_t>(xs.size()),
                                         static_cast<std::uint32_t>(breaks.size())};
  const GridView grid{2, axes.data(), begin.data(), breaks.data()};
  ASSERT_TRUE(oasis::rt::validate_grid(grid, 2));
  const auto ny = static_cast<std::uint32_t>(ys.size() - 1);
  std::uniform_real_distribution<double> x_of(-0.5, xs.back() + 0.5);
  std::uniform_real_distribution<double> y_of(-3.5, ys.back() + 0.5);
  for (int i = 0; i < 1'000'000; ++i) {
    double state[2] = {x_of(random), y_of(random)};
    if (i % 10 == 0) state[0] = xs[random() % xs.size()];  // exactly on a breakpoint
    if (i % 10 == 1) state[1] = std::nextafter(ys[random() % ys.size()], -10.0);
    const std::uint32_t kx = scan(xs, state[0]);
    const std::uint32_t ky = scan(ys, state[1]);
    const std::uint32_t expected =
        kx == kOutsideCell || ky == kOutsideCell ? kOutsideCell : kx * ny + ky;
    ASSERT_EQ(oasis::rt::locate_cell(grid, state, 2), expected)
        << "point (" << state[0] << ", " << state[1] << ")";
  }
}

}  // namespace
