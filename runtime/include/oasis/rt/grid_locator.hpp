// oasis/rt/grid_locator.hpp: point location in a gridded continuous abstraction.
//
// A continuous abstraction partitions the box of the variables its context attends to into a
// rectilinear grid: per relevant axis a strictly increasing list of breakpoints, the cells
// being the products of consecutive intervals in row-major order (the last axis varies
// fastest). The locator maps an observed continuous state to its cell with one binary search
// per axis: O(sum_i log n_i) comparisons, no allocation, no exceptions.
//
// Boundary rule (the compiler's, compiler/geom/grid.hpp): intervals are closed below and open
// above, [t_k, t_{k+1}), except the last interval of each axis, which also holds the domain's
// high end. A point with any relevant coordinate outside [t_0, t_n] (or NaN) is outside the
// domain: locate_cell returns kOutsideCell, which the abstraction maps to its outside block.
#pragma once

#include <cstddef>
#include <cstdint>

namespace oasis::rt {

/// Returned by locate_cell for a state outside the gridded domain.
inline constexpr std::uint32_t kOutsideCell = 0xFFFFFFFFu;

/// A rectilinear grid over some coordinates of the state vector. A view: owns nothing.
struct GridView {
  /// Number of gridded axes (the abstraction's relevant variables); at least 1.
  std::uint32_t dimension = 0;
  /// [dimension] index of each axis in the state vector.
  const std::uint32_t* axes = nullptr;
  /// [dimension + 1] axis i's breakpoints are breaks[break_begin[i] .. break_begin[i+1]-1];
  /// at least two per axis.
  const std::uint32_t* break_begin = nullptr;
  /// All breakpoints, each axis's strictly increasing and finite.
  const double* breaks = nullptr;
};

namespace detail {

/// The interval of a sorted list holding x, by the boundary rule; kOutsideCell if none.
inline std::uint32_t locate_interval(const double* t, std::uint32_t count, double x) noexcept {
  if (!(x >= t[0] && x <= t[count - 1])) return kOutsideCell;  // also NaN
  // The first breakpoint above x, by binary search over [1, count - 1].
  std::uint32_t low = 1;
  std::uint32_t high = count - 1;  // t[high] >= x: the high end closes the last interval
  while (low < high) {
    const std::uint32_t middle = low + (high - low) / 2;
    if (t[middle] > x) {
      high = middle;
    } else {
      low = middle + 1;
    }
  }
  return t[low] > x ? low - 1 : count - 2;
}

}  // namespace detail

/// Number of cells of the grid: the product of the interval counts.
inline std::uint64_t grid_cells(const GridView& grid) noexcept {
  std::uint64_t cells = 1;
  for (std::uint32_t i = 0; i < grid.dimension; ++i)
    cells *= grid.break_begin[i + 1] - grid.break_begin[i] - 1;
  return cells;
}

/// The row-major cell holding `state` (which has `state_size` coordinates, at least every
/// axis index + 1), or kOutsideCell. The grid must be valid (see validate_grid).
inline std::uint32_t locate_cell(const GridView& grid, const double* state,
                                 std::size_t state_size) noexcept {
  std::uint64_t cell = 0;
  for (std::uint32_t i = 0; i < grid.dimension; ++i) {
    if (grid.axes[i] >= state_size) return kOutsideCell;
    const std::uint32_t count = grid.break_begin[i + 1] - grid.break_begin[i];
    const std::uint32_t k =
        detail::locate_interval(grid.breaks + grid.break_begin[i], count, state[grid.axes[i]]);
    if (k == kOutsideCell) return kOutsideCell;
    cell = cell * (count - 1) + k;
  }
  return static_cast<std::uint32_t>(cell);
}

/// True when the grid is well formed: dimension >= 1, non-null arrays, break_begin starting
/// at 0 and rising by at least 2 per axis, every breakpoint finite and strictly increasing
/// within its axis, every axis index below `state_size`, and fewer than 2^32 - 1 cells.
/// Reads break_begin[0 .. dimension] and the breakpoints they cover, nothing else.
inline bool validate_grid(const GridView& grid, std::size_t state_size) noexcept {
  if (grid.dimension == 0 || grid.axes == nullptr || grid.break_begin == nullptr ||
      grid.breaks == nullptr || grid.break_begin[0] != 0)
    return false;
  std::uint64_t cells = 1;
  for (std::uint32_t i = 0; i < grid.dimension; ++i) {
    if (grid.axes[i] >= state_size) return false;
    const std::uint32_t begin = grid.break_begin[i];
    const std::uint32_t end = grid.break_begin[i + 1];
    if (end < begin || end - begin < 2) return false;
    for (std::uint32_t k = begin; k < end; ++k) {
      const double t = grid.breaks[k];
      if (!(t - t == 0)) return false;  // NaN or infinite
      if (k > begin && !(grid.breaks[k - 1] < t)) return false;
    }
    cells *= end - begin - 1;
    if (cells >= kOutsideCell) return false;
  }
  return true;
}

}  // namespace oasis::rt
