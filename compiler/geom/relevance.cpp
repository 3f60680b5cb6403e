#include "geom/relevance.hpp"

#include <deque>

#include "model/affine.hpp"
#include "support/text.hpp"

namespace oasis::geom {
namespace {

// The variables a reward condition reads (non-zero coefficients of its inequalities).
// Returns false when the condition is not polyhedral, which the front end normally refuses.
bool read_by_condition(const model::ModelIR& ir, const model::Expression& guard,
                       std::vector<bool>& read) {
  const auto constraints = model::polyhedral_constraints(guard, ir.continuous.size(), ir.regions);
  if (!constraints) return false;
  for (const model::LinearConstraint& constraint : *constraints) {
    for (std::size_t v = 0; v < constraint.coefficients.size(); ++v)
      if (sgn(constraint.coefficients[v]) != 0) read[v] = true;
  }
  return true;
}

void check_disturbances(const model::ModelIR& ir, const model::ContextIR& context,
                        std::vector<std::string>& failed) {
  for (std::size_t a = 0; a < context.dynamics.size(); ++a) {
    const auto& dynamics = context.dynamics[a];
    if (!dynamics) continue;
    for (std::size_t v = 0; v < dynamics->disturbance.size(); ++v) {
      const model::DisturbanceModel& w = dynamics->disturbance[v];
      // The language gives additive, state-independent disturbances, one per variable; a
      // model built otherwise (a future extension, a hand-made IR) is reported, not trusted.
      if (w.kind == model::DisturbanceModel::Kind::Bounded && w.first > w.second) {
        failed.push_back("the disturbance of " + quoted(ir.continuous[v].name) + " under " +
                         quoted(ir.actions[a]) + " is an empty interval");
      }
    }
  }
}

}  // namespace

Relevance analyse_relevance(const model::ModelIR& ir, std::size_t context_index) {
  const model::ContextIR& context = ir.contexts[context_index];
  const std::size_t n = ir.continuous.size();
  Relevance result;
  std::vector<bool> relevant(n, false);
  std::vector<std::string> reason(n);
  std::deque<std::uint32_t> pending;

  for (const model::Reward& reward : context.rewards) {
    std::vector<bool> read(n, false);
    if (!read_by_condition(ir, reward.guard, read)) {
      result.failed_conditions.push_back("a reward condition of context " + quoted(context.name) +
                                         " is not polyhedral");
    }
    if (!reward.value.is_constant()) {
      result.failed_conditions.push_back("a reward of context " + quoted(context.name) +
                                         " is not a constant");
    }
    for (std::uint32_t v = 0; v < n; ++v) {
      if (read[v] && !relevant[v]) {
        relevant[v] = true;
        reason[v] = "a reward condition";
        pending.push_back(v);
      }
    }
  }
  // Closure: whatever the next value of a relevant variable reads is relevant too.
  while (!pending.empty()) {
    const std::uint32_t i = pending.front();
    pending.pop_front();
    for (std::size_t a = 0; a < context.dynamics.size(); ++a) {
      const auto& dynamics = context.dynamics[a];
      if (!dynamics) continue;
      for (std::uint32_t j = 0; j < n; ++j) {
        if (relevant[j] || sgn(dynamics->matrix[i][j]) == 0) continue;
        relevant[j] = true;
        reason[j] =
            "the dynamics of " + quoted(ir.continuous[i].name) + " under " + quoted(ir.actions[a]);
        pending.push_back(j);
      }
    }
  }
  check_disturbances(ir, context, result.failed_conditions);
  for (std::uint32_t v = 0; v < n; ++v) {
    if (relevant[v]) {
      result.relevant.push_back(v);
      result.reasons.push_back(reason[v]);
    } else {
      result.ignored.push_back(v);
    }
  }
  return result;
}

ProjectedStep project_step(const model::AffineDynamics& affine, const Relevance& relevance) {
  const std::size_t d = relevance.relevant.size();
  ProjectedStep step{std::vector<std::vector<Rational>>(d, std::vector<Rational>(d)),
                     std::vector<Rational>(d)};
  for (std::size_t i = 0; i < d; ++i) {
    const std::uint32_t vi = relevance.relevant[i];
    for (std::size_t j = 0; j < d; ++j)
      step.matrix[i][j] = affine.matrix[vi][relevance.relevant[j]];
    step.offset[i] = affine.offset[vi];
  }
  return step;
}

Relevance full_state(const model::ModelIR& ir) {
  Relevance result;
  for (std::uint32_t v = 0; v < ir.continuous.size(); ++v) {
    result.relevant.push_back(v);
    result.reasons.push_back("the no-attention baseline keeps every variable");
  }
  return result;
}

}  // namespace oasis::geom
