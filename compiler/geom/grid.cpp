#include "geom/grid.hpp"

#include <algorithm>

namespace oasis::geom {

Grid::Grid(std::vector<std::vector<Rational>> breaks) : breaks_(std::move(breaks)) {
  const std::size_t d = breaks_.size();
  strides_.assign(d, 1);
  num_cells_ = d == 0 ? 0 : 1;
  for (std::size_t i = d; i-- > 0;) {
    strides_[i] = num_cells_;
    num_cells_ *= breaks_[i].size() - 1;
  }
  for (const auto& axis : breaks_) {
    std::vector<double> nearest;
    nearest.reserve(axis.size());
    for (const Rational& t : axis)
      nearest.push_back(to_double(t));
    breaks_double_.push_back(std::move(nearest));
  }
}

std::size_t Grid::cell_of(std::span<const std::uint32_t> index) const {
  std::size_t cell = 0;
  for (std::size_t i = 0; i < index.size(); ++i)
    cell += index[i] * strides_[i];
  return cell;
}

void Grid::index_of(std::size_t cell, std::span<std::uint32_t> index) const {
  for (std::size_t i = 0; i < dimension(); ++i) {
    index[i] = static_cast<std::uint32_t>(cell / strides_[i]);
    cell %= strides_[i];
  }
}

std::optional<std::uint32_t> Grid::locate(std::size_t axis, const Rational& x) const {
  const std::vector<Rational>& t = breaks_[axis];
  if (x < t.front() || x > t.back()) return std::nullopt;
  // The first break above x closes x's interval; the high end belongs to the last interval.
  const auto above = std::upper_bound(t.begin(), t.end(), x);
  if (above == t.end()) return static_cast<std::uint32_t>(t.size() - 2);
  return static_cast<std::uint32_t>(above - t.begin() - 1);
}

std::optional<std::uint32_t> Grid::locate(std::size_t axis, double x) const {
  const std::vector<double>& t = breaks_double_[axis];
  if (!(x >= t.front() && x <= t.back())) return std::nullopt;  // also refuses NaN
  const auto above = std::upper_bound(t.begin(), t.end(), x);
  if (above == t.end()) return static_cast<std::uint32_t>(t.size() - 2);
  return static_cast<std::uint32_t>(above - t.begin() - 1);
}

std::optional<std::size_t> Grid::locate(std::span<const double> point) const {
  std::size_t cell = 0;
  for (std::size_t i = 0; i < dimension(); ++i) {
    const auto k = locate(i, point[i]);
    if (!k) return std::nullopt;
    cell += *k * strides_[i];
  }
  return cell;
}

}  // namespace oasis::geom
