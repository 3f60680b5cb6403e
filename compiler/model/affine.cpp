#include "model/affine.hpp"

#include <utility>

namespace oasis::model {
namespace {

using model::Expression;
using model::LinearConstraint;
using model::Op;

AffineForm scaled(AffineForm form, const Rational& factor) {
  for (Rational& c : form.coefficients)
    c *= factor;
  form.constant *= factor;
  return form;
}

bool is_constant_form(const AffineForm& form) {
  for (const Rational& c : form.coefficients) {
    if (c != 0) return false;
  }
  return true;
}

// left - right, as the constraint (left - right) <= 0 or < 0.
LinearConstraint difference(const AffineForm& left, const AffineForm& right, bool strict) {
  LinearConstraint constraint;
  constraint.strict = strict;
  for (std::size_t i = 0; i < left.coefficients.size(); ++i) {
    constraint.coefficients.push_back(left.coefficients[i] - right.coefficients[i]);
  }
  constraint.bound = right.constant - left.constant;
  return constraint;
}

}  // namespace

std::optional<AffineForm> affine_form(const Expression& expr, std::size_t num_variables) {
  AffineForm form{std::vector<Rational>(num_variables), 0};
  switch (expr.op) {
    case Op::Constant:
      form.constant = expr.constant;
      return form;
    case Op::ContinuousVariable:
      form.coefficients[expr.slot] = 1;
      return form;
    case Op::Negate: {
      auto inner = affine_form(expr.operands[0], num_variables);
      if (!inner) return std::nullopt;
      return scaled(std::move(*inner), -1);
    }
    case Op::Add:
    case Op::Subtract: {
      auto left = affine_form(expr.operands[0], num_variables);
      auto right = affine_form(expr.operands[1], num_variables);
      if (!left || !right) return std::nullopt;
      const Rational sign = expr.op == Op::Add ? 1 : -1;
      for (std::size_t i = 0; i < num_variables; ++i) {
        left->coefficients[i] += sign * right->coefficients[i];
      }
      left->constant += sign * right->constant;
      return left;
    }
    case Op::Multiply: {
      auto left = affine_form(expr.operands[0], num_variables);
      auto right = affine_form(expr.operands[1], num_variables);
      if (!left || !right) return std::nullopt;
      if (is_constant_form(*left)) return scaled(std::move(*right), left->constant);
      if (is_constant_form(*right)) return scaled(std::move(*left), right->constant);
      return std::nullopt;
    }
    case Op::Divide: {
      auto left = affine_form(expr.operands[0], num_variables);
      auto right = affine_form(expr.operands[1], num_variables);
      if (!left || !right || !is_constant_form(*right) || right->constant == 0) return std::nullopt;
      return scaled(std::move(*left), 1 / right->constant);
    }
    default:
      return std::nullopt;
  }
}

namespace {

bool is_constant_form(const IntervalAffineForm& form) {
  for (const Interval& c : form.coefficients) {
    if (c.lo != 0 || c.hi != 0) return false;
  }
  return true;
}

IntervalAffineForm scaled(IntervalAffineForm form, Interval factor) {
  for (Interval& c : form.coefficients)
    c = c * factor;
  form.constant = form.constant * factor;
  return form;
}

// A function of a constant: its enclosure, or nullopt when the function refuses the range.
std::optional<Interval> constant_function(Op op, const std::vector<Interval>& args) {
  try {
    switch (op) {
      case Op::Sin:
        return sin(args[0]);
      case Op::Cos:
        return cos(args[0]);
      case Op::Tan:
        return tan(args[0]);
      case Op::Atan:
        return atan(args[0]);
      case Op::Exp:
        return exp(args[0]);
      case Op::Log:
        return log(args[0]);
      case Op::Sqrt:
        return sqrt(args[0]);
      case Op::Abs:
        return abs(args[0]);
      case Op::Min:
      case Op::Max: {
        Interval result = args[0];
        for (std::size_t i = 1; i < args.size(); ++i)
          result = op == Op::Min ? min(result, args[i]) : max(result, args[i]);
        return result;
      }
      default:
        return std::nullopt;
    }
  } catch (const IntervalError&) {
    return std::nullopt;
  }
}

}  // namespace

std::optional<IntervalAffineForm> interval_affine_form(const Expression& expr,
                                                       std::size_t num_variables) {
  IntervalAffineForm form{std::vector<Interval>(num_variables, Interval{0, 0}), Interval{0, 0}};
  const auto operand = [&](std::size_t i) {
    return interval_affine_form(expr.operands[i], num_variables);
  };
  try {
    switch (expr.op) {
      case Op::Constant:
        form.constant = from_rational(expr.constant);
        return form;
      case Op::ContinuousVariable:
        form.coefficients[expr.slot] = Interval{1, 1};
        return form;
      case Op::Negate: {
        auto inner = operand(0);
        if (!inner) return std::nullopt;
        return scaled(std::move(*inner), Interval{-1, -1});
      }
      case Op::Add:
      case Op::Subtract: {
        auto left = operand(0);
        auto right = operand(1);
        if (!left || !right) return std::nullopt;
        for (std::size_t i = 0; i < num_variables; ++i) {
          left->coefficients[i] = expr.op == Op::Add
                                      ? left->coefficients[i] + right->coefficients[i]
                                      : left->coefficients[i] - right->coefficients[i];
        }
        left->constant = expr.op == Op::Add ? left->constant + right->constant
                                            : left->constant - right->constant;
        return left;
      }
      case Op::Multiply: {
        auto left = operand(0);
        auto right = operand(1);
        if (!left || !right) return std::nullopt;
        if (is_constant_form(*left)) return scaled(std::move(*right), left->constant);
        if (is_constant_form(*right)) return scaled(std::move(*left), right->constant);
        return std::nullopt;
      }
      case Op::Divide: {
        auto left = operand(0);
        auto right = operand(1);
        if (!left || !right || !is_constant_form(*right)) return std::nullopt;
        return scaled(std::move(*left), Interval{1, 1} / right->constant);
      }
      case Op::Power: {
        auto base = operand(0);
        if (!base || !is_constant_form(*base)) return std::nullopt;
        if (!expr.operands[1].is_constant() || expr.operands[1].constant.get_den() != 1)
          return std::nullopt;
        form.constant = power(base->constant, expr.operands[1].constant.get_num().get_si());
        return form;
      }
      default: {
        std::vector<Interval> args;
        for (std::size_t i = 0; i < expr.operands.size(); ++i) {
          auto argument = operand(i);
          if (!argument || !is_constant_form(*argument)) return std::nullopt;
          args.push_back(argument->constant);
        }
        if (args.empty()) return std::nullopt;
        auto value = constant_function(expr.op, args);
        if (!value) return std::nullopt;
        form.constant = *value;
        return form;
      }
    }
  } catch (const IntervalError&) {
    return std::nullopt;
  }
}

std::optional<std::vector<LinearConstraint>> polyhedral_constraints(
    const Expression& expr, std::size_t num_variables, const std::vector<model::Region>& regions) {
  std::vector<LinearConstraint> constraints;
  switch (expr.op) {
    case Op::Constant:
      if (expr.constant != 0) return constraints;  // `true`: no constraint
      return std::nullopt;
    case Op::RegionIs:
      return regions.at(expr.slot).constraints;
    case Op::And: {
      auto left = polyhedral_constraints(expr.operands[0], num_variables, regions);
      auto right = polyhedral_constraints(expr.operands[1], num_variables, regions);
      if (!left || !right) return std::nullopt;
      left->insert(left->end(), right->begin(), right->end());
      return left;
    }
    case Op::Less:
    case Op::LessEqual:
    case Op::Greater:
    case Op::GreaterEqual:
    case Op::Equal: {
      auto left = affine_form(expr.operands[0], num_variables);
      auto right = affine_form(expr.operands[1], num_variables);
      if (!left || !right) return std::nullopt;
      const bool strict = expr.op == Op::Less || expr.op == Op::Greater;
      if (expr.op == Op::Less || expr.op == Op::LessEqual) {
        constraints.push_back(difference(*left, *right, strict));
      } else if (expr.op == Op::Greater || expr.op == Op::GreaterEqual) {
        constraints.push_back(difference(*right, *left, strict));
      } else {
        constraints.push_back(difference(*left, *right, false));
        constraints.push_back(difference(*right, *left, false));
      }
      return constraints;
    }
    default:
      return std::nullopt;
  }
}

}  // namespace oasis::model
