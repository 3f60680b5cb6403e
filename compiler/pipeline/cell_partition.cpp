#include "pipeline/cell_partition.hpp"

#include <algorithm>

#include "oasis/rt/bsp_locator.hpp"

namespace oasis::pipeline {

bool BspArrays::is_leaf(std::size_t node) const {
  return cell[node] != rt::kInternalNode;
}

std::size_t CellPartition::num_cells() const {
  if (bsp) return polytopes.size();
  std::size_t cells = 1;
  for (std::size_t axis = 0; axis < dimension(); ++axis)
    cells *= intervals(axis);
  return cells;
}

std::size_t CellPartition::cell_of(std::span<const std::uint32_t> index) const {
  std::size_t cell = 0;
  for (std::size_t axis = 0; axis < dimension(); ++axis)
    cell = cell * intervals(axis) + index[axis];
  return cell;
}

void CellPartition::index_of(std::size_t cell, std::span<std::uint32_t> index) const {
  for (std::size_t axis = dimension(); axis-- > 0;) {
    index[axis] = static_cast<std::uint32_t>(cell % intervals(axis));
    cell /= intervals(axis);
  }
}

std::optional<std::uint32_t> CellPartition::locate(std::size_t axis, double x) const {
  const std::vector<double>& t = breaks[axis];
  if (!(x >= t.front() && x <= t.back())) return std::nullopt;
  const auto above = std::upper_bound(t.begin(), t.end(), x);
  if (above == t.end()) return static_cast<std::uint32_t>(t.size() - 2);
  return static_cast<std::uint32_t>(above - t.begin() - 1);
}

}  // namespace oasis::pipeline
