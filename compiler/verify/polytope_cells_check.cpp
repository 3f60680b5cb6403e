#include "verify/polytope_cells_check.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "oasis/rt/bsp_locator.hpp"
#include "verify/cell_geometry.hpp"
#include "verify/guard_reading.hpp"
#include "verify/number_text.hpp"
#include "verify/row_distance.hpp"

namespace oasis::verify {
namespace {

using Problem = std::optional<std::string>;

// a.x <= c over the whole state vector, in doubles.
struct LinearForm {
  std::vector<double> coefficients;
  double bound = 0;
};

// A reward of the context as the checks read it: its value and its condition's linear forms
// (nullopt when the condition is not polyhedral), converted from the spec once.
struct RewardForm {
  double value = 0;
  std::optional<std::vector<LinearForm>> condition;
};

std::vector<RewardForm> reward_forms(const model::ModelIR& ir, std::size_t context) {
  std::vector<RewardForm> forms;
  for (const model::Reward& reward : ir.contexts[context].rewards) {
    RewardForm form{to_double(reward.value.constant), std::nullopt};
    const auto constraints = guard_constraints(reward.guard, ir.continuous.size(), ir.regions);
    if (constraints) {
      form.condition.emplace();
      for (const model::LinearConstraint& constraint : *constraints) {
        LinearForm linear{{}, to_double(constraint.bound)};
        for (const Rational& a : constraint.coefficients)
          linear.coefficients.push_back(to_double(a));
        form.condition->push_back(std::move(linear));
      }
    }
    forms.push_back(std::move(form));
  }
  return forms;
}

// ---- one and two dimensions: cells as polygons -------------------------------------------

struct PlanarCells {
  std::vector<Point2> domain;
  std::vector<std::vector<Point2>> cells;
};

PlanarCells planar_cells(const model::ModelIR& ir, const rt::AbstractionView& abs,
                         const std::vector<std::vector<PathStep>>& paths) {
  PlanarCells planar;
  const auto& x = ir.continuous[abs.grid.axes[0]];
  const bool two_d = abs.grid.dimension == 2;
  const double y0 = two_d ? to_double(ir.continuous[abs.grid.axes[1]].low) : 0;
  const double y1 = two_d ? to_double(ir.continuous[abs.grid.axes[1]].high) : 1;
  planar.domain = rectangle(to_double(x.low), to_double(x.high), y0, y1);
  for (const auto& path : paths)
    planar.cells.push_back(cell_polygon(planar.domain, path));
  return planar;
}

Problem check_areas(const PlanarCells& planar) {
  const double total = area(planar.domain);
  double sum = 0;
  for (std::size_t c = 0; c < planar.cells.size(); ++c) {
    const double a = area(planar.cells[c]);
    if (!(a > 1e-12 * total)) return "cell " + std::to_string(c) + " is empty or flat";
    sum += a;
  }
  if (std::fabs(sum - total) > 1e-9 * total)
    return "the cells' areas sum to " + number_text(sum) + ", the domain's is " +
           number_text(total);
  return std::nullopt;
}

// The reward of a cell from the spec: each condition holds on all of it or on none of it
// (up to a face); nullopt when one cuts through it.
std::optional<double> planar_reward(const std::vector<RewardForm>& rewards,
                                    const rt::AbstractionView& abs,
                                    const std::vector<Point2>& polygon) {
  double total = 0;
  for (const RewardForm& reward : rewards) {
    if (!reward.condition) return std::nullopt;
    bool all = true;
    bool none = false;
    for (const LinearForm& form : *reward.condition) {
      double low = HUGE_VAL;
      double high = -HUGE_VAL;
      for (const Point2& corner : polygon) {
        double value = form.coefficients[abs.grid.axes[0]] * corner.first;
        if (abs.grid.dimension == 2) value += form.coefficients[abs.grid.axes[1]] * corner.second;
        low = std::min(low, value);
        high = std::max(high, value);
      }
      const double slack = 1e-9 * std::max(1.0, std::fabs(form.bound));
      if (low > form.bound - slack) none = true;
      if (high > form.bound + slack) all = false;
    }
    if (none) continue;
    if (!all) return std::nullopt;
    total += reward.value;
  }
  return total;
}

Problem check_planar_rewards(const std::vector<RewardForm>& rewards, const rt::AbstractionView& abs,
                             const PlanarCells& planar) {
  for (std::size_t c = 0; c < planar.cells.size(); ++c) {
    const std::optional<double> reward = planar_reward(rewards, abs, planar.cells[c]);
    if (!reward) return "a reward condition cuts through cell " + std::to_string(c);
    const double carried = abs.block_reward[abs.cell_block[c]];
    if (std::fabs(carried - *reward) > 1e-12 * std::max(1.0, std::fabs(*reward)))
      return "cell " + std::to_string(c) + " has reward " + number_text(*reward) +
             " but its block " + std::to_string(abs.cell_block[c]) + " says " +
             number_text(carried);
  }
  return std::nullopt;
}

// The successor distribution over blocks from `x` under action a: uniform on the box
// M x + t + W (every relevant axis disturbed), its area in each cell, the rest outside.
std::optional<std::vector<double>> planar_successor_blocks(const model::ModelIR& ir,
                                                           std::size_t context, std::size_t a,
                                                           const rt::AbstractionView& abs,
                                                           const PlanarCells& planar,
                                                           const Point2& x) {
  const model::AffineDynamics& dynamics = *ir.contexts[context].dynamics[a];
  const std::uint32_t d = abs.grid.dimension;
  double low[2] = {0, 0};
  double high[2] = {1, 1};
  const double at[2] = {x.first, x.second};
  for (std::uint32_t i = 0; i < d; ++i) {
    const std::uint32_t v = abs.grid.axes[i];
    const model::DisturbanceModel& w = dynamics.disturbance[v];
    if (w.kind != model::DisturbanceModel::Kind::Bounded || !(w.first < w.second))
      return std::nullopt;  // a point on some axis: not checked here
    double mean = to_double(dynamics.offset[v]);
    for (std::uint32_t j = 0; j < d; ++j)
      mean += to_double(dynamics.matrix[v][abs.grid.axes[j]]) * at[j];
    low[i] = mean + to_double(w.first);
    high[i] = mean + to_double(w.second);
  }
  const std::vector<Point2> box = rectangle(low[0], high[0], low[1], high[1]);
  const double box_area = area(box);
  std::vector<double> by_block(abs.num_blocks, 0);
  double inside = 0;
  for (std::size_t c = 0; c < planar.cells.size(); ++c) {
    std::vector<Point2> part = box;
    const std::vector<Point2>& cell = planar.cells[c];
    // Clip the box by every edge of the (convex) cell polygon.
    double orientation = 0;
    for (std::size_t k = 0; k < cell.size(); ++k) {
      const Point2& p = cell[k];
      const Point2& q = cell[(k + 1) % cell.size()];
      orientation += p.first * q.second - q.first * p.second;
    }
    for (std::size_t k = 0; k < cell.size() && !part.empty(); ++k) {
      const Point2& p = cell[k];
      const Point2& q = cell[(k + 1) % cell.size()];
      // Inside is on the left of p->q for a counter-clockwise polygon.
      double ax = q.second - p.second;
      double ay = p.first - q.first;
      if (orientation < 0) {
        ax = -ax;
        ay = -ay;
      }
      part = clip(part, ax, ay, ax * p.first + ay * p.second);
    }
    const double mass = part.size() >= 3 ? area(part) / box_area : 0;
    by_block[abs.cell_block[c]] += mass;
    inside += mass;
  }
  by_block[abs.outside_block] += std::max(0.0, 1 - inside);
  return by_block;
}

Problem check_planar_rows(const model::ModelIR& ir, std::size_t context,
                          const rt::AbstractionView& abs, const PlanarCells& planar,
                          std::uint32_t actions, std::size_t& checked) {
  const std::size_t cells = planar.cells.size();
  const std::size_t stride = std::max<std::size_t>(1, cells / 24);
  for (std::size_t c = 0; c < cells; c += stride) {
    const std::vector<Point2>& polygon = planar.cells[c];
    Point2 centroid{0, 0};
    for (const Point2& corner : polygon) {
      centroid.first += corner.first / static_cast<double>(polygon.size());
      centroid.second += corner.second / static_cast<double>(polygon.size());
    }
    // Points a hair inside the corners (a corner itself may lie on a face whose image the
    // rest of the cell only touches: a set of measure zero, docs/geometry.md), and the centroid.
    std::vector<Point2> points{centroid};
    for (const Point2& corner : polygon)
      points.emplace_back(corner.first + 1e-7 * (centroid.first - corner.first),
                          corner.second + 1e-7 * (centroid.second - corner.second));
    const std::uint32_t block = abs.cell_block[c];
    for (const Point2& x : points) {
      for (std::uint32_t a = 0; a < actions; ++a) {
        auto p = planar_successor_blocks(ir, context, a, abs, planar, x);
        if (!p) continue;
        const std::size_t row = std::size_t{block} * actions + a;
        for (auto e = abs.quotient.choice_begin[row]; e < abs.quotient.choice_begin[row + 1]; ++e)
          (*p)[abs.quotient.target[e]] -= abs.quotient.probability[e];
        const double variation = total_variation(*p);
        ++checked;
        if (variation > abs.epsilon + 1e-7)
          return row_too_far(c, ir.actions[a], variation, abs.epsilon);
      }
    }
  }
  return std::nullopt;
}

// ---- any dimension ------------------------------------------------------------------------

std::vector<double> random_point(const model::ModelIR& ir, std::mt19937_64& random, double margin) {
  std::vector<double> point(ir.continuous.size());
  for (std::size_t v = 0; v < point.size(); ++v) {
    const double low = to_double(ir.continuous[v].low);
    const double high = to_double(ir.continuous[v].high);
    point[v] = std::uniform_real_distribution<double>(low - margin * (high - low),
                                                      high + margin * (high - low))(random);
  }
  return point;
}

bool in_domain(const model::ModelIR& ir, const rt::AbstractionView& abs, const double* x) {
  for (std::uint32_t i = 0; i < abs.grid.dimension; ++i) {
    const auto& v = ir.continuous[abs.grid.axes[i]];
    if (!(x[i] >= to_double(v.low) && x[i] <= to_double(v.high))) return false;
  }
  return true;
}

// The locator against plain membership, and (in any dimension) the reward at every point
// against its cell's block.
Problem check_points(const model::ModelIR& ir, const std::vector<RewardForm>& rewards,
                     const rt::AbstractionView& abs,
                     const std::vector<std::vector<PathStep>>& paths, std::size_t& points) {
  std::mt19937_64 random(7);
  std::size_t work = 0;
  for (const auto& path : paths)
    work += path.size() + 1;
  points = std::clamp<std::size_t>(20'000'000 / std::max<std::size_t>(1, work), 500, 20'000);
  std::vector<double> relevant(abs.grid.dimension);
  for (std::size_t k = 0; k < points; ++k) {
    const std::vector<double> point = random_point(ir, random, 0.05);
    for (std::uint32_t i = 0; i < abs.grid.dimension; ++i)
      relevant[i] = point[abs.grid.axes[i]];
    std::uint32_t member = rt::kOutsideCell;
    if (in_domain(ir, abs, relevant.data())) {
      for (std::uint32_t c = 0; c < paths.size(); ++c) {
        if (!on_path(paths[c], relevant.data())) continue;
        if (member != rt::kOutsideCell) return "a point lies in two cells";
        member = c;
      }
      if (member == rt::kOutsideCell) return "a point of the domain lies in no cell";
    }
    if (rt::locate_partition_cell(abs.grid, abs.bsp, point.data(), point.size()) != member)
      return "the locator and plain membership disagree at a point";
    if (member == rt::kOutsideCell) continue;
    double reward = 0;
    for (const RewardForm& r : rewards) {
      bool holds = r.condition.has_value();
      for (const LinearForm& form : r.condition.value_or(std::vector<LinearForm>{}))
        holds = holds && dot(form.coefficients, point.data()) <= form.bound;
      if (holds) reward += r.value;
    }
    if (reward != abs.block_reward[abs.cell_block[member]])
      return "at a point of cell " + std::to_string(member) + " the spec's reward is " +
             number_text(reward) + ", its block's " +
             number_text(abs.block_reward[abs.cell_block[member]]);
  }
  return std::nullopt;
}

}  // namespace

PolytopeCellsVerdict check_polytope_cells(const model::ModelIR& ir, std::size_t context,
                                          const rt::AbstractionView& abs, std::uint32_t actions,
                                          bool with_rows) {
  PolytopeCellsVerdict verdict;
  const std::vector<std::vector<PathStep>> paths = cell_paths(abs);
  const std::vector<RewardForm> rewards = reward_forms(ir, context);
  std::size_t points = 0;
  verdict.problem = check_points(ir, rewards, abs, paths, points);
  if (verdict.problem) return verdict;
  verdict.summary = std::to_string(paths.size()) + " polytope cells; locator and rewards at " +
                    std::to_string(points) + " points ok";
  if (abs.grid.dimension > 2) return verdict;
  const PlanarCells planar = planar_cells(ir, abs, paths);
  verdict.problem = check_areas(planar);
  if (!verdict.problem) verdict.problem = check_planar_rewards(rewards, abs, planar);
  if (verdict.problem) return verdict;
  verdict.summary += "; cells non-empty, areas summing to the domain's, rewards constant per cell";
  if (!with_rows) return verdict;
  std::size_t checked = 0;
  verdict.problem = check_planar_rows(ir, context, abs, planar, actions, checked);
  if (!verdict.problem)
    verdict.summary +=
        "; " + std::to_string(checked) + " sampled rows within epsilon " + number_text(abs.epsilon);
  return verdict;
}

}  // namespace oasis::verify
