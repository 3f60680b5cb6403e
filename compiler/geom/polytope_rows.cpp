#include "geom/polytope_rows.hpp"

#include <algorithm>

#include "geom/bsp_box_split.hpp"
#include "geom/polytope_error_bound.hpp"

namespace oasis::geom {
namespace {

bool inside_undisturbed_domain(const PolytopeGeometry& geometry, const AffineStep& step,
                               const Point& mean) {
  for (std::size_t i = 0; i < mean.size(); ++i) {
    if (step.disturbance[i]) continue;
    if (mean[i] < geometry.domain_low[i] || mean[i] > geometry.domain_high[i]) return false;
  }
  return true;
}

// The disturbance box around `mean`: its corners on the disturbed axes, and the mean's value on
// each undisturbed one (where the box is a slice).
struct DisturbedBox {
  std::vector<std::optional<Rational>> fixed;
  Point low;
  Point high;
};

DisturbedBox disturbed_box(const AffineStep& step, const Point& mean) {
  DisturbedBox box;
  box.fixed.resize(mean.size());
  for (std::size_t i = 0; i < mean.size(); ++i) {
    if (step.disturbance[i]) {
      box.low.push_back(mean[i] + step.disturbance[i]->low);
      box.high.push_back(mean[i] + step.disturbance[i]->high);
    } else {
      box.fixed[i] = mean[i];
    }
  }
  return box;
}

// vol(B ∩ Q) / vol(B) in the disturbed coordinates, on the slice at the mean's undisturbed
// coordinates. Only the constraints of Q that cut the box are kept, so that a box well
// inside one cell costs nothing and the vertex enumeration stays small.
Rational box_share(const Polytope& cell, const AffineStep& step, const Point& mean,
                   const Rational& box_volume) {
  const auto [fixed, low, high] = disturbed_box(step, mean);
  Polytope clipped = Polytope::box(low, high);
  const Polytope slice = cell.slice(fixed);
  for (const HalfSpace& h : slice.constraints()) {
    Rational least = 0;
    Rational most = 0;
    for (std::size_t j = 0; j < h.normal.size(); ++j) {
      least += std::min(h.normal[j] * low[j], h.normal[j] * high[j]);
      most += std::max(h.normal[j] * low[j], h.normal[j] * high[j]);
    }
    if (least >= h.bound && most > h.bound) return 0;  // the box is beyond this face
    if (most > h.bound) clipped.add(h);                // else it holds on the whole box
  }
  return clipped.volume() / box_volume;
}

}  // namespace

Rational box_volume_of(const AffineStep& step) {
  Rational volume = 1;
  for (const auto& w : step.disturbance)
    if (w) volume *= w->width();
  return volume;
}

namespace {

bool is_disturbed(const AffineStep& step) {
  return std::any_of(step.disturbance.begin(), step.disturbance.end(),
                     [](const auto& w) { return w.has_value(); });
}

// The general path for boxes of three or more free dimensions: one exact volume per cell the
// box may meet.
void general_shares(const BspTree& tree, const AffineStep& step, const Point& mean,
                    const Rational& box_volume, RowParts& row) {
  auto range = [&](const std::vector<Rational>& normal) {
    const Rational centre = dot(normal, mean);
    ValueRange r{centre, centre};
    add_disturbance(step, normal, r);
    return r;
  };
  Rational inside = 0;
  for (const std::uint32_t cell : tree.cells_meeting(range)) {
    const Rational p = box_share(tree.cells()[cell].polytope, step, mean, box_volume);
    if (sgn(p) <= 0) continue;
    inside += p;
    row.shares.emplace_back(cell, p);
  }
  if (inside < 1) row.shares.emplace_back(tree.num_cells(), 1 - inside);
}

}  // namespace

RowParts successor_parts(const PolytopeGeometry& geometry, const BspTree& tree,
                         const AffineStep& step, const Point& from,
                         std::span<const RoundedBspNode> rounded, const BspSubtrees* subtrees) {
  Point mean = step.offset;
  for (std::size_t i = 0; i < mean.size(); ++i)
    mean[i] += dot(step.matrix[i], from);
  RowParts row;
  const std::size_t outside = tree.num_cells();
  if (!inside_undisturbed_domain(geometry, step, mean)) {
    row.shares.emplace_back(outside, 1);
    return row;
  }
  if (!is_disturbed(step)) {  // a point: one cell (the undisturbed check put it in the domain)
    row.shares.emplace_back(*tree.locate(mean), 1);
    return row;
  }
  const Rational box_volume = box_volume_of(step);
  const auto [fixed, low, high] = disturbed_box(step, mean);
  auto pieces = split_box(tree, fixed, low, high, rounded, subtrees);
  if (!pieces) {
    general_shares(tree, step, mean, box_volume, row);
    return row;
  }
  row.whole_subtrees = std::move(pieces->whole_subtrees);
  row.shares.reserve(pieces->cut.size() + 1);
  const bool unit_box = box_volume == 1;  // common (disturbances of width 1): no division
  for (auto& [cell, measure] : pieces->cut) {
    if (!unit_box) measure /= box_volume;
    row.shares.emplace_back(cell, std::move(measure));
  }
  // The pieces partition the box's part inside the domain; the rest leaves it.
  if (pieces->inside < box_volume)
    row.shares.emplace_back(outside, 1 - pieces->inside / box_volume);
  return row;
}

std::vector<std::pair<std::size_t, Rational>> successor_row(
    const PolytopeGeometry& geometry, const BspTree& tree, const AffineStep& step,
    const Point& from, std::span<const RoundedBspNode> rounded) {
  RowParts parts = successor_parts(geometry, tree, step, from, rounded, nullptr);
  std::vector<std::pair<std::size_t, Rational>> row = std::move(parts.shares);
  std::sort(row.begin(), row.end(), [](const auto& p, const auto& q) { return p.first < q.first; });
  return row;
}

}  // namespace oasis::geom
