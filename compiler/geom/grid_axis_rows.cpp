#include "geom/grid_axis_rows.hpp"

#include <algorithm>

#include "geom/grid_gaussian_axis.hpp"

namespace oasis::geom {

void AxisRowBuilder::axis_row(const AxisDynamics& action, std::size_t i,
                              const std::vector<Rational>& centre, AxisRow& row) const {
  row.entries.clear();
  // The image of the centre without its disturbance.
  Rational image = action.offset[i];
  for (std::size_t j = 0; j < centre.size(); ++j)
    if (sgn(action.matrix[i][j]) != 0) image += action.matrix[i][j] * centre[j];
  const Disturbance& w = action.disturbance[i];
  switch (w.kind) {
    case Disturbance::Kind::None:
      point_row(i, image, row);
      return;
    case Disturbance::Kind::Uniform:
      uniform_row(i, image, w.uniform, row);
      return;
    case Disturbance::Kind::Gaussian:
      gaussian_row(i, image, w.gaussian, row);
      return;
  }
}

// A point: one interval, or outside.
void AxisRowBuilder::point_row(std::size_t i, const Rational& point, AxisRow& row) const {
  const auto k = grid_.locate(i, point);
  row.inside = k ? 1 : 0;
  if (k) row.entries.emplace_back(*k, RationalPool::kOne);
}

// Uniform on image + [low, high]: each interval's share of the overlap, exactly. Only the
// two end intervals are cut by the support; the shares of those between are the same for
// every cell and come from whole_shares().
void AxisRowBuilder::uniform_row(std::size_t i, const Rational& image, const Interval& w,
                                 AxisRow& row) const {
  const Rational low = image + w.low;
  const Rational high = image + w.high;
  const Rational width = w.high - w.low;
  const std::vector<Rational>& t = grid_.breaks(i);
  const std::vector<ValueId>& whole = whole_shares(i, width);
  // The mass inside the domain: the support's overlap with it, over the width.
  const Rational inside_low = std::max(low, t.front());
  const Rational inside_high = std::min(high, t.back());
  row.inside = inside_low < inside_high ? (inside_high - inside_low) / width : Rational(0);
  if (sgn(row.inside) == 0) return;
  // The first interval whose upper end is above `low`, and the last whose lower end is below
  // `high`.
  auto first = static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), low) - t.begin());
  first = first == 0 ? 0 : first - 1;
  auto last = static_cast<std::size_t>(std::lower_bound(t.begin(), t.end(), high) - t.begin());
  last = std::min(last, t.size() - 1) - 1;
  for (std::size_t k = first; k <= last; ++k) {
    if (low <= t[k] && t[k + 1] <= high) {
      row.entries.emplace_back(static_cast<std::uint32_t>(k), whole[k]);
      continue;
    }
    const Rational overlap = std::min(high, t[k + 1]) - std::max(low, t[k]);
    if (sgn(overlap) <= 0) continue;
    row.entries.emplace_back(static_cast<std::uint32_t>(k), values_.intern(overlap / width));
  }
}

const std::vector<ValueId>& AxisRowBuilder::whole_shares(std::size_t i,
                                                         const Rational& width) const {
  const auto [slot, inserted] = shares_.try_emplace({i, width});
  if (inserted) {
    const std::vector<Rational>& t = grid_.breaks(i);
    for (std::size_t k = 0; k + 1 < t.size(); ++k)
      slot->second.push_back(values_.intern((t[k + 1] - t[k]) / width));
  }
  return slot->second;
}

// Normal(image + w.mean, w.deviation²): the intervals under its truncated support, to the
// tolerance of geom/grid_gaussian_axis.hpp, which the context's epsilon includes.
void AxisRowBuilder::gaussian_row(std::size_t i, const Rational& image, const Gaussian& w,
                                  AxisRow& row) const {
  row.inside = 0;
  const Rational mean = image + w.mean;
  for (auto& [k, p] : gaussian_interval_probabilities(mean, w.deviation, grid_.breaks(i))) {
    row.inside += p;
    row.entries.emplace_back(k, values_.intern(p));
  }
}

std::vector<Rational> cell_centre(const Grid& grid, std::span<const std::uint32_t> index) {
  std::vector<Rational> centre(index.size());
  for (std::size_t i = 0; i < index.size(); ++i) {
    const std::vector<Rational>& t = grid.breaks(i);
    centre[i] = (t[index[i]] + t[index[i] + 1]) / 2;
  }
  return centre;
}

Rational cell_reward(const GridGeometry& geometry, const Grid& grid,
                     std::span<const std::uint32_t> index) {
  Rational total = 0;
  for (const RewardBox& reward : geometry.rewards) {
    bool inside = true;
    for (std::size_t i = 0; i < index.size() && inside; ++i) {
      const std::vector<Rational>& t = grid.breaks(i);
      inside = reward.box[i].low <= t[index[i]] && t[index[i] + 1] <= reward.box[i].high;
    }
    if (inside) total += reward.value;
  }
  return total;
}

}  // namespace oasis::geom
