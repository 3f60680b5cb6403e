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
