#pragma once
// One axis of a grid cell's successor distribution (geom/grid_mdp.hpp states the model): the
// intervals the axis's successor coordinate lands in, each with its exact probability, and the
// exact mass that stays inside the domain. A cell's row under an action is the product of its
// axis rows. Shared by the materialised finite MDP (grid_mdp.hpp) and the rows kept in
// product form (grid_product_rows.hpp), so both read the same numbers.

#include <cstdint>
#include <map>
#include <span>
#include <utility>
#include <vector>

#include "geom/grid.hpp"
#include "geom/grid_geometry.hpp"
#include "support/rational.hpp"

namespace oasis::geom {

struct AxisRow {
  std::vector<std::pair<std::uint32_t, ValueId>> entries;  // (interval, probability), increasing
  Rational inside;                                         // Σ of the entries' probabilities
};

class AxisRowBuilder {
 public:
  AxisRowBuilder(const Grid& grid, RationalPool& values) : grid_(grid), values_(values) {}

  // The successor distribution of axis i from a cell with centre `centre` under `action`.
  void axis_row(const AxisDynamics& action, std::size_t i, const std::vector<Rational>& centre,
                AxisRow& row) const;

 private:
  void point_row(std::size_t i, const Rational& point, AxisRow& row) const;
  void uniform_row(std::size_t i, const Rational& image, const Interval& w, AxisRow& row) const;
  void gaussian_row(std::size_t i, const Rational& image, const Gaussian& w, AxisRow& row) const;
  // The probability of each whole interval of axis i under a uniform disturbance of `width`:
  // its length over the width, interned once per axis and width.
  const std::vector<ValueId>& whole_shares(std::size_t i, const Rational& width) const;

  const Grid& grid_;
  RationalPool& values_;
  mutable std::map<std::pair<std::size_t, Rational>, std::vector<ValueId>> shares_;
};

// The centre of the cell with per-axis interval indices `index`.
std::vector<Rational> cell_centre(const Grid& grid, std::span<const std::uint32_t> index);

// Σ of the rewards whose box holds the cell (boxes are unions of cells by construction).
Rational cell_reward(const GridGeometry& geometry, const Grid& grid,
                     std::span<const std::uint32_t> index);

}  // namespace oasis::geom
