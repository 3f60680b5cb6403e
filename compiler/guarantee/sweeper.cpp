#include "guarantee/sweeper.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace oasis::guarantee {
namespace {

// Covers, with a wide margin, the outward rounding of the two robust values compared when an
// action is skipped on its cached value (each is within about 1e-12 of exact even for rows of
// a thousand entries per axis in four dimensions).
constexpr double kLipschitzSlack = 1e-9;

// `x` as a float at least (at most) as large.
float float_up(double x) {
  const auto f = static_cast<float>(x);
  return f < x ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}
float float_down(double x) {
  const auto f = static_cast<float>(x);
  return f > x ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
}

}  // namespace

SweepMode sweep_mode(const model::GuaranteeObjective& objective) {
  if (objective.kind == model::GuaranteeObjective::Kind::Safety) return SweepMode::Safety;
  return objective.exactly_at_step ? SweepMode::ReachAt : SweepMode::Reach;
}

double Sweeper::terminal(std::size_t cell, Bound bound) const {
  if (mode_ == SweepMode::Safety) return safe(cell, bound) ? 1 : 0;
  return target(cell, bound) ? 1 : 0;
}

double Sweeper::fixed(std::size_t cell, Bound bound) const {
  if (mode_ == SweepMode::Reach && target(cell, bound)) return 1;
  if (!safe(cell, bound)) return 0;
  return -1;
}

std::vector<double> Sweeper::fixed_or_zero(Bound bound) const {
  std::vector<double> values(mdp_.grid.cells);
  for (std::size_t c = 0; c < values.size(); ++c)
    values[c] = std::max(0.0, fixed(c, bound));
  return values;
}

RobustGame Sweeper::game(Bound bound) const {
  if (bound == Bound::Lower) return RobustGame{false, 0, 0};
  return RobustGame{true, cells_.outside_may_succeed ? 1.0 : 0.0, 1};
}

double Sweeper::best_action(std::size_t cell, const ValueTable& values, Bound bound,
                            std::uint32_t& action) {
  const double constant = fixed(cell, bound);
  if (constant >= 0) return constant;
  double best = -1;
  for (std::uint32_t a = 0; a < mdp_.actions.size(); ++a) {
    const double q = action_value(cell, values, a, bound, chooser_rounding(bound));
    if (q > best) {
      best = q;
      action = a;
    }
  }
  return best;
}

Sweeper::Choice Sweeper::update(std::size_t cell, const ValueTable& values, Bound bound,
                                std::uint32_t& action, double switch_gain, Rounding rounding) {
  const double constant = fixed(cell, bound);
  if (constant >= 0) return {constant, constant};
  RobustGame g = game(bound);
  g.round_against_chooser = rounding != chooser_rounding(bound);
  const std::size_t actions = mdp_.actions.size();
  if (cached_value_.empty()) {
    cached_value_.assign(mdp_.grid.cells * actions, std::numeric_limits<float>::infinity());
    cached_drift_.assign(mdp_.grid.cells * actions, 0);
  }
  const auto value_of = [&](std::size_t a) {
    const double q = robust_value(mdp_, mdp_.row(cell, a), values, g, scratch_);
    cached_value_[cell * actions + a] = float_up(q);
    cached_drift_[cell * actions + a] = float_down(values.drift_base());
    return q;
  };
  const double current = value_of(action);
  double best = current;
  std::uint32_t best_index = action;
  for (std::size_t a = 0; a < actions; ++a) {
    if (a == action) continue;
    const std::size_t slot = cell * actions + a;
    const double reach = double{cached_value_[slot]} +
                         (values.drift() - double{cached_drift_[slot]}) + kLipschitzSlack;
    if (reach < best) continue;
    const double q = value_of(a);
    if (q > best) {
      best = q;
      best_index = static_cast<std::uint32_t>(a);
    }
  }
  if (best > current + switch_gain) {
    action = best_index;
    return {best, best};
  }
  return {best, current};
}

double Sweeper::action_value(std::size_t cell, const ValueTable& values, std::uint32_t action,
                             Bound bound, Rounding rounding) {
  const double constant = fixed(cell, bound);
  if (constant >= 0) return constant;
  RobustGame g = game(bound);
  g.round_against_chooser = rounding != chooser_rounding(bound);
  return robust_value(mdp_, mdp_.row(cell, action), values, g, scratch_);
}

}  // namespace oasis::guarantee
