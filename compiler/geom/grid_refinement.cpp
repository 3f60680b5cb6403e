#include "geom/grid_refinement.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "geom/grid_gaussian_axis.hpp"
#include "support/text.hpp"

namespace oasis::geom {
namespace {

using Breaks = std::vector<std::set<Rational>>;

Breaks mandatory_breaks(const GridGeometry& geometry) {
  Breaks breaks(geometry.dimension());
  for (std::size_t i = 0; i < geometry.dimension(); ++i) {
    breaks[i].insert(geometry.domain[i].low);
    breaks[i].insert(geometry.domain[i].high);
  }
  for (const RewardBox& reward : geometry.rewards) {
    for (std::size_t i = 0; i < geometry.dimension(); ++i) {
      const Interval& domain = geometry.domain[i];
      for (const Rational& t : {reward.box[i].low, reward.box[i].high})
        if (t > domain.low && t < domain.high) breaks[i].insert(t);
    }
  }
  return breaks;
}

bool stochastic_somewhere(const GridGeometry& geometry, std::size_t axis) {
  return std::any_of(geometry.actions.begin(), geometry.actions.end(),
                     [&](const AxisDynamics& a) { return a.disturbance[axis].present(); });
}

// The length over which a disturbance spreads a unit of probability: its width when uniform,
// s·√(2π) when Gaussian, so that a shift δ costs at most |δ| / unit in total variation.
double spread_unit(const Disturbance& w) {
  if (w.kind == Disturbance::Kind::Uniform) return to_double(w.uniform.high - w.uniform.low);
  return to_double(w.gaussian.deviation) * to_double(sqrt_two_pi_below());
}

// The narrowest disturbance on an axis: the unit its cells are measured in.
double narrowest_unit(const GridGeometry& geometry, std::size_t axis) {
  double narrowest = HUGE_VAL;
  for (const AxisDynamics& action : geometry.actions) {
    if (action.disturbance[axis].present())
      narrowest = std::min(narrowest, spread_unit(action.disturbance[axis]));
  }
  return narrowest;
}

// Cuts every segment between consecutive breaks of `axis` into pieces of at most `step`, but
// never into more than `max_pieces` (a target that no grid meets must not ask for 10^12
// breakpoints: the cell budget refuses such grids anyway).
std::set<Rational> subdivided(const std::set<Rational>& breaks, double step,
                              std::size_t max_pieces) {
  std::set<Rational> out = breaks;
  for (auto it = breaks.begin(); std::next(it) != breaks.end(); ++it) {
    const Rational& low = *it;
    const Rational length = *std::next(it) - low;
    const double pieces =
        std::min(std::ceil(to_double(length) / step), static_cast<double>(max_pieces));
    const long count = static_cast<long>(std::max(1.0, pieces));
    for (long k = 1; k < count; ++k)
      out.insert(low + length * Rational(k, count));
  }
  return out;
}

std::size_t cell_count(const Breaks& breaks) {
  double cells = 1;
  for (const auto& axis : breaks)
    cells *= static_cast<double>(axis.size() - 1);
  return cells > 1e18 ? static_cast<std::size_t>(1e18) : static_cast<std::size_t>(cells);
}

// The largest half-width of the cells of every axis.
std::vector<Rational> widest_half_widths(const Breaks& breaks) {
  std::vector<Rational> half(breaks.size());
  for (std::size_t i = 0; i < breaks.size(); ++i) {
    for (auto it = breaks[i].begin(); std::next(it) != breaks[i].end(); ++it)
      half[i] = std::max(half[i], Rational((*std::next(it) - *it) / 2));
  }
  return half;
}

// What computing Gaussian rows in floating point may cost under `action`: each axis's
// tolerance (geom/grid_gaussian_axis.hpp); the axes' errors add, as their distributions multiply.
Rational numeric_error(const AxisDynamics& action, const Breaks& breaks) {
  Rational total = 0;
  for (std::size_t i = 0; i < breaks.size(); ++i)
    if (action.disturbance[i].kind == Disturbance::Kind::Gaussian)
      total += gaussian_row_tolerance(breaks[i].size() - 1);
  return total;
}

Rational partition_error(const GridGeometry& geometry, const Breaks& breaks) {
  const std::vector<Rational> half = widest_half_widths(breaks);
  Rational worst = 0;
  for (const AxisDynamics& action : geometry.actions)
    worst = std::max(worst, Rational(cell_error(action, half) + numeric_error(action, breaks)));
  return worst;
}

// Breaks of the stochastic axes for cells of `scale` times each axis's narrowest disturbance.
Breaks with_scale(const GridGeometry& geometry, const Breaks& mandatory, double scale,
                  std::size_t max_pieces) {
  Breaks breaks = mandatory;
  for (std::size_t i = 0; i < geometry.dimension(); ++i) {
    if (stochastic_somewhere(geometry, i))
      breaks[i] = subdivided(mandatory[i], scale * narrowest_unit(geometry, i), max_pieces);
  }
  return breaks;
}

// What a scale makes of the grid, without building its breakpoints: per axis, the widest
// cell's half-width and the number of cells (as with_scale would cut them). Choosing the scale
// asks this some hundred times; building up to a budget's worth of exact breakpoints each time
// took minutes on a domain of [0 .. 1e300] before the grid was even chosen (issue 37).
struct GridShape {
  std::vector<Rational> half_widths;
  std::vector<double> intervals;
};

GridShape shape_at(const GridGeometry& geometry, const Breaks& mandatory, double scale,
                   std::size_t max_pieces) {
  GridShape shape{std::vector<Rational>(geometry.dimension()),
                  std::vector<double>(geometry.dimension())};
  for (std::size_t i = 0; i < geometry.dimension(); ++i) {
    const bool cut = stochastic_somewhere(geometry, i);
    const double step = cut ? scale * narrowest_unit(geometry, i) : 0;
    for (auto it = mandatory[i].begin(); std::next(it) != mandatory[i].end(); ++it) {
      const Rational length = *std::next(it) - *it;
      const double pieces =
          cut ? std::min(std::ceil(to_double(length) / step), static_cast<double>(max_pieces))
              : 1.0;
      const double count = std::max(1.0, pieces);
      shape.intervals[i] += count;
      shape.half_widths[i] = std::max(shape.half_widths[i],
                                      Rational(length / (2 * Rational(static_cast<long>(count)))));
    }
  }
  return shape;
}

double shape_cells(const GridShape& shape) {
  double cells = 1;
  for (const double intervals : shape.intervals)
    cells *= intervals;
  return cells;
}

double shape_error(const GridGeometry& geometry, const GridShape& shape) {
  Rational worst = 0;
  for (const AxisDynamics& action : geometry.actions) {
    Rational error = cell_error(action, shape.half_widths);
    for (std::size_t i = 0; i < shape.intervals.size(); ++i)
      if (action.disturbance[i].kind == Disturbance::Kind::Gaussian)
        error += gaussian_row_tolerance(static_cast<std::size_t>(shape.intervals[i]));
    worst = std::max(worst, error);
  }
  return to_double(worst);
}

// The pre-images of every break of axis i under every action that moves i without a
// disturbance, until closed. False when the budget is passed.
bool close_under_preimages(const GridGeometry& geometry, Breaks& breaks, std::size_t max_breaks,
                           std::size_t& rounds) {
  for (std::size_t i = 0; i < geometry.dimension(); ++i) {
    const Interval& domain = geometry.domain[i];
    std::vector<Rational> pending(breaks[i].begin(), breaks[i].end());
    while (!pending.empty()) {
      ++rounds;
      std::vector<Rational> found;
      for (const AxisDynamics& action : geometry.actions) {
        if (action.disturbance[i].present()) continue;
        for (const Rational& t : pending) {
          const Rational preimage = (t - action.offset[i]) / action.matrix[i][i];
          if (preimage > domain.low && preimage < domain.high &&
              breaks[i].insert(preimage).second) {
            found.push_back(preimage);
          }
        }
      }
      if (breaks[i].size() > max_breaks) return false;
      pending = std::move(found);
    }
  }
  return true;
}

}  // namespace

Rational shift_cost(const Disturbance& w) {
  if (w.kind == Disturbance::Kind::Uniform) return 1 / Rational(w.uniform.high - w.uniform.low);
  if (w.kind == Disturbance::Kind::Gaussian)
    return 1 / Rational(w.gaussian.deviation * sqrt_two_pi_below());
  return 0;
}

Rational cell_error(const AxisDynamics& action, std::span<const Rational> half_widths) {
  const std::size_t d = half_widths.size();
  Rational worst = 0;
  // Every vertex v - c = (±r_1, ..., ±r_d); 2^d of them, d is the number of relevant axes.
  for (std::size_t signs = 0; signs < (std::size_t{1} << d); ++signs) {
    Rational total = 0;
    for (std::size_t i = 0; i < d; ++i) {
      const Disturbance& w = action.disturbance[i];
      if (!w.present()) continue;
      Rational shift = 0;
      for (std::size_t j = 0; j < d; ++j) {
        const Rational term = action.matrix[i][j] * half_widths[j];
        shift += ((signs >> j) & 1U) != 0 ? -term : term;
      }
      // The rounded coefficients' error moves the mean by at most approximation[i] more.
      total += (abs(shift) + action.approximation[i]) * shift_cost(w);
    }
    worst = std::max(worst, total);
  }
  return worst;
}

std::optional<GridPartition> partition_grid(const GridGeometry& geometry, const GridTarget& target,
                                            std::string& error) {
  const Breaks mandatory = mandatory_breaks(geometry);
  // ε grows with the scale of the cells and the cell count shrinks: take the coarsest scale
  // that meets the target, or, when that needs too many cells, the finest that fits the
  // budget. Bisection on doubles chooses the grid; its ε is then computed exactly.
  auto meets = [&](double scale) {
    return shape_error(geometry, shape_at(geometry, mandatory, scale, target.max_cells + 1)) <=
           target.epsilon;
  };
  auto fits = [&](double scale) {
    return shape_cells(shape_at(geometry, mandatory, scale, target.max_cells + 1)) <=
           static_cast<double>(target.max_cells);
  };
  double fine = 0;  // meets the target (a scale of 0 would, with infinitely many cells)
  double coarse = 1;
  while (meets(coarse) && coarse < 1e6)
    coarse *= 2;
  for (int step = 0; step < 40; ++step) {
    const double middle = (fine + coarse) / 2;
    (meets(middle) ? fine : coarse) = middle;
  }
  double scale = fine > 0 ? fine : coarse;
  if (!fits(scale)) {
    // Up to the whole domain in one piece per segment: a domain of 1e300 fits only at a
    // scale near 1e300 (its bound then says how far the budget is from the target).
    double crowded = scale;  // too many cells
    double sparse = scale;
    while (!fits(sparse) && sparse < 1e300)
      sparse *= 2;
    for (int step = 0; step < 60; ++step) {
      const double middle = crowded + (sparse - crowded) / 2;
      (fits(middle) ? sparse : crowded) = middle;
    }
    scale = sparse;
  }
  Breaks breaks = with_scale(geometry, mandatory, scale, target.max_cells + 1);
  GridPartition result;
  if (!close_under_preimages(geometry, breaks, target.max_cells + 1, result.preimage_rounds) ||
      cell_count(breaks) > target.max_cells) {
    error = "context " + quoted(geometry.context) + ": the partition needs more than " +
            std::to_string(target.max_cells) +
            " cells (pre-images of deterministic moves do not close, or the error target "
            "is too fine); raise --max-cells or the target epsilon";
    return std::nullopt;
  }
  result.epsilon = partition_error(geometry, breaks);
  result.met = to_double(result.epsilon) <= target.epsilon;
  std::vector<std::vector<Rational>> axes;
  for (const auto& axis : breaks)
    axes.emplace_back(axis.begin(), axis.end());
  result.grid = Grid(std::move(axes));
  return result;
}

}  // namespace oasis::geom
