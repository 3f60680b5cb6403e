#pragma once
// A rectilinear grid over a box: per axis a strictly increasing list of breakpoints from the
// domain's low end to its high end; the cells are the products of consecutive intervals, in
// row-major order (the last axis varies fastest). Breakpoints are exact rationals; their
// nearest doubles are kept for point location.
//
// Boundary rule (what a point on a shared face belongs to): intervals are closed below and
// open above, [t_k, t_{k+1}), except the last one of each axis, which also holds the domain's
// high end. So every point of the closed domain is in exactly one cell.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "support/rational.hpp"

namespace oasis::geom {

class Grid {
 public:
  Grid() = default;
  // `breaks[i]`: at least two strictly increasing values per axis.
  explicit Grid(std::vector<std::vector<Rational>> breaks);

  [[nodiscard]] std::size_t dimension() const { return breaks_.size(); }
  [[nodiscard]] std::size_t num_cells() const { return num_cells_; }
  [[nodiscard]] std::size_t intervals(std::size_t axis) const { return breaks_[axis].size() - 1; }
  [[nodiscard]] const std::vector<Rational>& breaks(std::size_t axis) const {
    return breaks_[axis];
  }
  [[nodiscard]] const std::vector<double>& breaks_double(std::size_t axis) const {
    return breaks_double_[axis];
  }

  // Row-major cell index of per-axis interval indices, and back.
  [[nodiscard]] std::size_t cell_of(std::span<const std::uint32_t> index) const;
  void index_of(std::size_t cell, std::span<std::uint32_t> index) const;

  // The interval of `axis` holding `x` (boundary rule above); nullopt outside the domain.
  [[nodiscard]] std::optional<std::uint32_t> locate(std::size_t axis, const Rational& x) const;
  [[nodiscard]] std::optional<std::uint32_t> locate(std::size_t axis, double x) const;
  // The cell holding a point given per axis, or nullopt outside the domain.
  [[nodiscard]] std::optional<std::size_t> locate(std::span<const double> point) const;

 private:
  std::vector<std::vector<Rational>> breaks_;
  std::vector<std::vector<double>> breaks_double_;
  std::vector<std::size_t> strides_;
  std::size_t num_cells_ = 0;
};

}  // namespace oasis::geom
