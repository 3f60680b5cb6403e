#include "geom/grid_geometry.hpp"

#include <algorithm>

#include "model/affine.hpp"
#include "support/text.hpp"

namespace oasis::geom {
namespace {

// Position of variable `v` among the relevant axes, or -1.
int axis_of(const Relevance& relevance, std::uint32_t v) {
  const auto found = std::find(relevance.relevant.begin(), relevance.relevant.end(), v);
  return found == relevance.relevant.end() ? -1
                                           : static_cast<int>(found - relevance.relevant.begin());
}

bool reward_box(const model::ModelIR& ir, const model::Reward& reward, const Relevance& relevance,
                const std::vector<Interval>& domain, RewardBox& out, std::string& error) {
  const auto constraints =
      model::polyhedral_constraints(reward.guard, ir.continuous.size(), ir.regions);
  if (!constraints || !reward.value.is_constant()) {
    error = "a reward is not a constant on a polyhedral condition";
    return false;
  }
  out.box = domain;
  out.value = reward.value.constant;
  for (const model::LinearConstraint& constraint : *constraints) {
    int axis = -1;
    Rational coefficient;
    for (std::uint32_t v = 0; v < constraint.coefficients.size(); ++v) {
      if (sgn(constraint.coefficients[v]) == 0) continue;
      if (axis >= 0) {
        error =
            "a reward condition is not an axis-aligned box (an inequality reads two "
            "variables), which the grid cannot follow";
        return false;
      }
      axis = axis_of(relevance, v);
      coefficient = constraint.coefficients[v];
    }
    if (axis < 0) {
      // No variable: a constant inequality, true or false everywhere.
      if (constraint.bound < 0 || (constraint.strict && constraint.bound == 0)) {
        out.box[0].high = out.box[0].low;  // empty
      }
      continue;
    }
    // coefficient * x <= bound: an upper bound when the coefficient is positive.
    const Rational limit = constraint.bound / coefficient;
    Interval& side = out.box[static_cast<std::size_t>(axis)];
    if (coefficient > 0) {
      side.high = std::min(side.high, limit);
    } else {
      side.low = std::max(side.low, limit);
    }
  }
  return true;
}

void axis_dynamics(const model::AffineDynamics& affine, const Relevance& relevance,
                   AxisDynamics& out) {
  const std::size_t d = relevance.relevant.size();
  ProjectedStep projected = project_step(affine, relevance);
  out.matrix = std::move(projected.matrix);
  out.offset = std::move(projected.offset);
  out.disturbance.assign(d, Disturbance{});
  out.approximation.assign(d, Rational(0));
  for (std::size_t i = 0; i < d; ++i) {
    const std::uint32_t vi = relevance.relevant[i];
    if (!affine.approximation.empty()) out.approximation[i] = affine.approximation[vi];
    const model::DisturbanceModel& w = affine.disturbance[vi];
    using Kind = model::DisturbanceModel::Kind;
    Disturbance& axis = out.disturbance[i];
    if (w.kind == Kind::Gaussian) {  // the checker ensures a positive deviation
      axis.kind = Disturbance::Kind::Gaussian;
      axis.gaussian = {w.first, w.second};
    }
    if (w.kind == Kind::Bounded && w.first < w.second) {
      axis.kind = Disturbance::Kind::Uniform;
      axis.uniform = {w.first, w.second};
    }
    if (w.kind == Kind::Bounded && w.first == w.second) out.offset[i] += w.first;  // a point
  }
}

// Axes without a disturbance get their cells from pre-images of intervals, which needs
// x'_i = a x_i + b with a != 0 under every action.
bool check_deterministic_axes(const GridGeometry& geometry, std::string& error) {
  for (std::size_t i = 0; i < geometry.dimension(); ++i) {
    for (const AxisDynamics& action : geometry.actions) {
      if (action.disturbance[i].present()) continue;
      if (action.approximation[i] != 0) {
        error = "variable " + quoted(geometry.axis_names[i]) +
                " has no disturbance and irrational coefficients, whose pre-images the grid "
                "cannot compute exactly";
        return false;
      }
      for (std::size_t j = 0; j < geometry.dimension(); ++j) {
        const bool own = j == i;
        if (own ? sgn(action.matrix[i][j]) == 0 : sgn(action.matrix[i][j]) != 0) {
          error = "variable " + quoted(geometry.axis_names[i]) +
                  " has no disturbance and its next value " +
                  (own ? "does not depend on itself" : "reads another variable") +
                  ", which the grid cannot follow";
          return false;
        }
      }
    }
  }
  return true;
}

}  // namespace

bool GridGeometry::deterministic(std::size_t axis) const {
  return std::none_of(actions.begin(), actions.end(),
                      [&](const AxisDynamics& a) { return a.disturbance[axis].present(); });
}

std::optional<GridGeometry> grid_geometry(const model::ModelIR& ir, std::size_t context,
                                          const Relevance& relevance, std::string& error) {
  const model::ContextIR& source = ir.contexts[context];
  GridGeometry geometry;
  geometry.context = source.name;
  geometry.relevance = relevance;
  if (relevance.relevant.empty()) {
    error = "context " + quoted(source.name) + " attends to no variable (its rewards read none)";
    return std::nullopt;
  }
  for (const std::uint32_t v : relevance.relevant) {
    geometry.axis_names.push_back(ir.continuous[v].name);
    geometry.domain.push_back({ir.continuous[v].low, ir.continuous[v].high});
  }
  for (const model::Reward& reward : source.rewards) {
    RewardBox box;
    if (!reward_box(ir, reward, relevance, geometry.domain, box, error)) {
      error = "context " + quoted(source.name) + ": " + error;
      return std::nullopt;
    }
    geometry.rewards.push_back(std::move(box));
  }
  for (std::size_t a = 0; a < ir.actions.size(); ++a) {
    if (!source.dynamics[a]) {
      error = "context " + quoted(source.name) + ": action " + quoted(ir.actions[a]) +
              " has no dynamics";
      return std::nullopt;
    }
    AxisDynamics dynamics;
    axis_dynamics(*source.dynamics[a], relevance, dynamics);
    geometry.actions.push_back(std::move(dynamics));
  }
  if (!check_deterministic_axes(geometry, error)) {
    error = "context " + quoted(source.name) + ": " + error;
    return std::nullopt;
  }
  return geometry;
}

}  // namespace oasis::geom
