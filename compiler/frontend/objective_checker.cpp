#include "frontend/objective_checker.hpp"

#include "support/limits.hpp"

namespace oasis::frontend {
namespace {

std::optional<Rational> checked_discount(const ast::Expr& expr, bool has_horizon,
                                         DiagnosticEngine& diagnostics,
                                         ExpressionChecker& expressions) {
  auto value = expressions.constant_number(expr, "the discount");
  if (!value) return std::nullopt;
  if (*value <= 0 || *value > 1) {
    diagnostics.error(expr.range, "discount must be in (0, 1], not " + describe(*value));
  } else if (*value == 1 && !has_horizon) {
    diagnostics.error(expr.range,
                      "discount 1 over an infinite horizon may give infinite values: write a "
                      "discount below 1, or 'horizon N' for undiscounted rewards over N steps");
  } else if (*value < 1 && to_double(*value) == 1) {
    diagnostics.error(expr.range, "discount 1 - " + describe(1 - *value) +
                                      " rounds to 1 in double precision, where the policy "
                                      "is solved; write at most 1 - 2^-53 (0.9999999999999999)");
  } else {
    return value;
  }
  return std::nullopt;
}

}  // namespace

void check_objective(const std::optional<ast::Setting>& discount,
                     const std::optional<ast::Setting>& horizon, model::ModelIR& ir,
                     DiagnosticEngine& diagnostics, ExpressionChecker& expressions) {
  if (discount && horizon) {
    diagnostics.error(horizon->range, "give a 'discount' or a 'horizon', not both");
  }
  if (discount) {
    ir.objective_range = discount->value->range;
    ir.objective.discount =
        checked_discount(*discount->value, horizon.has_value(), diagnostics, expressions);
  }
  if (horizon) {
    ir.objective_range = horizon->value->range;
    auto value = expressions.constant_integer(*horizon->value, "the horizon");
    if (value && (*value < 1 || *value > limits::kMaxHorizon)) {
      diagnostics.error(horizon->value->range, "horizon must be between 1 and 10^9 steps");
    } else if (value) {
      ir.objective.horizon = static_cast<std::uint32_t>(*value);
    }
  }
}

}  // namespace oasis::frontend
