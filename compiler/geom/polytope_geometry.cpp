#include "geom/polytope_geometry.hpp"

#include <algorithm>

#include "model/affine.hpp"
#include "support/text.hpp"

namespace oasis::geom {
namespace {

bool reward_region(const model::ModelIR& ir, const model::Reward& reward,
                   const PolytopeGeometry& geometry, PolytopeReward& out, std::string& error) {
  const auto constraints =
      model::polyhedral_constraints(reward.guard, ir.continuous.size(), ir.regions);
  if (!constraints || !reward.value.is_constant()) {
    error = "a reward is not a constant on a polyhedral condition";
    return false;
  }
  if (reward.action) {
    error = "a reward depends on the action; the polytope path handles state rewards only";
    return false;
  }
  const std::vector<std::uint32_t>& relevant = geometry.relevance.relevant;
  out.region = geometry.domain();
  out.value = reward.value.constant;
  for (const model::LinearConstraint& constraint : *constraints) {
    HalfSpace row{std::vector<Rational>(relevant.size(), 0), constraint.bound};
    for (std::uint32_t v = 0; v < constraint.coefficients.size(); ++v) {
      if (sgn(constraint.coefficients[v]) == 0) continue;
      const auto axis = std::find(relevant.begin(), relevant.end(), v);
      if (axis == relevant.end()) {
        error = "a reward condition reads " + quoted(ir.continuous[v].name) +
                ", which the context does not attend to";
        return false;
      }
      row.normal[static_cast<std::size_t>(axis - relevant.begin())] = constraint.coefficients[v];
    }
    out.region.add(row);  // a false constant makes the region empty, a true one vanishes
  }
  return true;
}

bool affine_step(const model::ModelIR& ir, const model::AffineDynamics& affine,
                 const Relevance& relevance, const std::string& action, AffineStep& out,
                 std::string& error) {
  const std::size_t d = relevance.relevant.size();
  for (const std::uint32_t v : relevance.relevant) {
    if (!affine.approximation.empty() && affine.approximation[v] != 0) {
      error = "action " + quoted(action) + " has irrational coefficients (" +
              quoted(ir.continuous[v].name) +
              "'s next value), which the polytope path cannot hold exactly; the grid path can";
      return false;
    }
  }
  ProjectedStep projected = project_step(affine, relevance);
  out.matrix = std::move(projected.matrix);
  out.offset = std::move(projected.offset);
  out.disturbance.assign(d, std::nullopt);
  for (std::size_t i = 0; i < d; ++i) {
    const std::uint32_t vi = relevance.relevant[i];
    const model::DisturbanceModel& w = affine.disturbance[vi];
    using Kind = model::DisturbanceModel::Kind;
    if (w.kind == Kind::Gaussian) {
      error = "the disturbance of " + quoted(ir.continuous[vi].name) + " under " + quoted(action) +
              " is Gaussian; the polytope path handles uniform boxes only";
      return false;
    }
    if (w.kind != Kind::Bounded) continue;
    if (w.first < w.second) {
      out.disturbance[i] = UniformDisturbance{w.first, w.second};
    } else {
      out.offset[i] += w.first;  // a zero-width disturbance is a constant shift
    }
  }
  return true;
}

}  // namespace

bool AffineStep::has_undisturbed_axis() const {
  return std::any_of(disturbance.begin(), disturbance.end(),
                     [](const auto& w) { return !w.has_value(); });
}

std::optional<PolytopeGeometry> polytope_geometry(const model::ModelIR& ir, std::size_t context,
                                                  const Relevance& relevance, std::string& error) {
  const model::ContextIR& source = ir.contexts[context];
  auto fail = [&](const std::string& reason) {
    error = "context " + quoted(source.name) + ": " + reason;
    return std::nullopt;
  };
  if (relevance.relevant.empty()) return fail("it attends to no variable (its rewards read none)");
  PolytopeGeometry geometry;
  geometry.context = source.name;
  geometry.relevance = relevance;
  for (const std::uint32_t v : relevance.relevant) {
    geometry.axis_names.push_back(ir.continuous[v].name);
    geometry.domain_low.push_back(ir.continuous[v].low);
    geometry.domain_high.push_back(ir.continuous[v].high);
  }
  for (const model::Reward& reward : source.rewards) {
    PolytopeReward region;
    std::string reason;
    if (!reward_region(ir, reward, geometry, region, reason)) return fail(reason);
    geometry.rewards.push_back(std::move(region));
  }
  for (std::size_t a = 0; a < ir.actions.size(); ++a) {
    if (!source.dynamics[a]) return fail("action " + quoted(ir.actions[a]) + " has no dynamics");
    AffineStep step;
    std::string reason;
    if (!affine_step(ir, *source.dynamics[a], relevance, ir.actions[a], step, reason))
      return fail(reason);
    geometry.actions.push_back(std::move(step));
  }
  return geometry;
}

}  // namespace oasis::geom
