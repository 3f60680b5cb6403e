#include "guarantee/objective_cells.hpp"

namespace oasis::guarantee {
namespace {

// The extremes of a·x over the closed box, exactly (the breakpoints are doubles, hence
// rationals).
struct Range {
  Rational low;
  Rational high;
};

Range linear_range(const model::LinearConstraint& constraint, const std::vector<Rational>& low,
                   const std::vector<Rational>& high) {
  Range range{0, 0};
  for (std::size_t i = 0; i < low.size(); ++i) {
    const Rational& a = constraint.coefficients[i];
    if (a == 0) continue;
    const Rational at_low = a * low[i];
    const Rational at_high = a * high[i];
    range.low += a > 0 ? at_low : at_high;
    range.high += a > 0 ? at_high : at_low;
  }
  return range;
}

// All of the box satisfies every constraint.
bool box_inside(const std::vector<model::LinearConstraint>& set, const std::vector<Rational>& low,
                const std::vector<Rational>& high) {
  for (const auto& constraint : set) {
    const Range range = linear_range(constraint, low, high);
    if (constraint.strict ? !(range.high < constraint.bound) : !(range.high <= constraint.bound))
      return false;
  }
  return true;
}

// Some point of the box may satisfy every constraint: each one alone meets the box (a
// superset of "the conjunction meets the box", which is the sound side for upper bounds).
bool box_may_meet(const std::vector<model::LinearConstraint>& set, const std::vector<Rational>& low,
                  const std::vector<Rational>& high) {
  for (const auto& constraint : set) {
    if (linear_range(constraint, low, high).low > constraint.bound) return false;
  }
  return true;
}

// The set provably lies in the domain box: for every axis, some constraint bounds it from
// above and one from below within the domain's range (empty: the set is the domain).
bool inside_domain(const std::vector<model::LinearConstraint>& set, const model::ModelIR& ir) {
  if (set.empty()) return true;
  for (std::size_t i = 0; i < ir.continuous.size(); ++i) {
    bool above = false;
    bool below = false;
    for (const auto& constraint : set) {
      bool only_axis = true;
      for (std::size_t j = 0; j < constraint.coefficients.size(); ++j)
        if (j != i && constraint.coefficients[j] != 0) only_axis = false;
      const Rational& a = constraint.coefficients[i];
      if (!only_axis || a == 0) continue;
      const Rational bound = constraint.bound / a;  // a x <= b: x <= b/a (a > 0) or x >= b/a
      if (a > 0 && bound <= ir.continuous[i].high) above = true;
      if (a < 0 && bound >= ir.continuous[i].low) below = true;
    }
    if (!above || !below) return false;
  }
  return true;
}

}  // namespace

ObjectiveCells objective_cells(const model::GuaranteeObjective& objective, const model::ModelIR& ir,
                               const UniformGrid& grid) {
  ObjectiveCells cells;
  const bool reach = objective.kind == model::GuaranteeObjective::Kind::ReachAvoid;
  const std::size_t d = grid.dimension();
  cells.target_lower.assign(grid.cells, 0);
  cells.target_upper.assign(grid.cells, 0);
  cells.safe_lower.assign(grid.cells, 0);
  cells.safe_upper.assign(grid.cells, 0);
  std::vector<Rational> low(d);
  std::vector<Rational> high(d);
  for (std::size_t cell = 0; cell < grid.cells; ++cell) {
    for (std::size_t i = 0; i < d; ++i) {
      const std::size_t k = grid.coordinate(cell, i);
      low[i] = Rational(grid.breaks[i][k]);
      high[i] = Rational(grid.breaks[i][k + 1]);
    }
    cells.safe_lower[cell] = box_inside(objective.safe, low, high);
    cells.safe_upper[cell] = box_may_meet(objective.safe, low, high);
    if (reach) {
      cells.target_lower[cell] = box_inside(objective.target, low, high);
      cells.target_upper[cell] = box_may_meet(objective.target, low, high);
    }
  }
  cells.outside_may_succeed =
      !(inside_domain(objective.safe, ir) && (!reach || inside_domain(objective.target, ir)));
  return cells;
}

}  // namespace oasis::guarantee
