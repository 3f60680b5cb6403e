#include "verify/guard_reading.hpp"

#include <algorithm>

namespace oasis::verify {
namespace {

using model::Expression;
using model::LinearConstraint;
using model::Op;

// An expression's exact values at the origin (index 0) and at the unit points e_1 .. e_n.
using PointValues = std::vector<Rational>;

bool is_constant(const PointValues& values) {
  return std::all_of(values.begin(), values.end(),
                     [&](const Rational& v) { return v == values.front(); });
}

// Evaluates `expr` at the n + 1 points; nullopt when it is not affine, which evaluation at
// finitely many points cannot show by itself: a product or quotient needs a constant side,
// and anything but + - * / is refused.
std::optional<PointValues> values_at_points(const Expression& expr, std::size_t n) {
  switch (expr.op) {
    case Op::Constant:
      return PointValues(n + 1, expr.constant);
    case Op::ContinuousVariable: {
      PointValues values(n + 1, Rational(0));
      values.at(expr.slot + 1) = 1;
      return values;
    }
    case Op::Negate: {
      auto values = values_at_points(expr.operands[0], n);
      if (values)
        for (Rational& v : *values)
          v = -v;
      return values;
    }
    case Op::Add:
    case Op::Subtract:
    case Op::Multiply:
    case Op::Divide:
      break;
    default:
      return std::nullopt;
  }
  auto left = values_at_points(expr.operands[0], n);
  const auto right = values_at_points(expr.operands[1], n);
  if (!left || !right) return std::nullopt;
  if (expr.op == Op::Multiply && !is_constant(*left) && !is_constant(*right)) return std::nullopt;
  if (expr.op == Op::Divide && (!is_constant(*right) || right->front() == 0)) return std::nullopt;
  for (std::size_t p = 0; p <= n; ++p) {
    Rational& v = (*left)[p];
    const Rational& w = (*right)[p];
    if (expr.op == Op::Add) v += w;
    if (expr.op == Op::Subtract) v -= w;
    if (expr.op == Op::Multiply) v *= w;
    if (expr.op == Op::Divide) v /= w;
  }
  return left;
}

// low - high <= 0 (or < 0) as a.x <= b: a_i = (low - high)(e_i) - (low - high)(0), b = -(low -
// high)(0).
LinearConstraint at_most(const PointValues& low, const PointValues& high, bool strict) {
  LinearConstraint constraint;
  constraint.strict = strict;
  const Rational at_origin = low[0] - high[0];
  for (std::size_t p = 1; p < low.size(); ++p)
    constraint.coefficients.push_back(low[p] - high[p] - at_origin);
  constraint.bound = -at_origin;
  return constraint;
}

bool read_into(const Expression& expr, std::size_t n, const std::vector<model::Region>& regions,
               std::vector<LinearConstraint>& out) {
  switch (expr.op) {
    case Op::Constant:
      return expr.constant != 0;  // `true` adds nothing; `false` is no polyhedron we check
    case Op::RegionIs: {
      const auto& constraints = regions.at(expr.slot).constraints;
      out.insert(out.end(), constraints.begin(), constraints.end());
      return true;
    }
    case Op::And:
      return read_into(expr.operands[0], n, regions, out) &&
             read_into(expr.operands[1], n, regions, out);
    case Op::Less:
    case Op::LessEqual:
    case Op::Greater:
    case Op::GreaterEqual:
    case Op::Equal:
      break;
    default:
      return false;
  }
  const auto left = values_at_points(expr.operands[0], n);
  const auto right = values_at_points(expr.operands[1], n);
  if (!left || !right) return false;
  const bool strict = expr.op == Op::Less || expr.op == Op::Greater;
  if (expr.op != Op::Greater && expr.op != Op::GreaterEqual)
    out.push_back(at_most(*left, *right, strict));
  if (expr.op != Op::Less && expr.op != Op::LessEqual)
    out.push_back(at_most(*right, *left, strict));
  return true;
}

}  // namespace

std::optional<std::vector<LinearConstraint>> guard_constraints(
    const Expression& guard, std::size_t num_variables, const std::vector<model::Region>& regions) {
  std::vector<LinearConstraint> constraints;
  if (!read_into(guard, num_variables, regions, constraints)) return std::nullopt;
  return constraints;
}

}  // namespace oasis::verify
