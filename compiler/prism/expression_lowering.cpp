#include "prism/expression_lowering.hpp"

#include <algorithm>
#include <string>
#include <utility>

#include "support/text.hpp"

namespace oasis::prism {
namespace {

using model::Expression;
using model::Op;
using model::Type;

bool numeric(Type type) {
  return type == Type::Int || type == Type::Real;
}

Expression make(Op op, Type type, std::vector<Expression> operands, SourceRange range) {
  Expression expr;
  expr.op = op;
  expr.type = type;
  expr.operands = std::move(operands);
  expr.range = range;
  return expr;
}

struct BinaryOperator {
  std::string_view spelling;
  Op op;
  enum class Kind { Arithmetic, Division, Comparison, Equality, Logic } kind;
};

constexpr BinaryOperator kBinaryOperators[] = {
    {"+", Op::Add, BinaryOperator::Kind::Arithmetic},
    {"-", Op::Subtract, BinaryOperator::Kind::Arithmetic},
    {"*", Op::Multiply, BinaryOperator::Kind::Arithmetic},
    {"/", Op::Divide, BinaryOperator::Kind::Division},
    {"<", Op::Less, BinaryOperator::Kind::Comparison},
    {"<=", Op::LessEqual, BinaryOperator::Kind::Comparison},
    {">", Op::Greater, BinaryOperator::Kind::Comparison},
    {">=", Op::GreaterEqual, BinaryOperator::Kind::Comparison},
    {"=", Op::Equal, BinaryOperator::Kind::Equality},
    {"!=", Op::NotEqual, BinaryOperator::Kind::Equality},
    {"<=>", Op::Equal, BinaryOperator::Kind::Logic},
    {"&", Op::And, BinaryOperator::Kind::Logic},
    {"|", Op::Or, BinaryOperator::Kind::Logic},
    {"=>", Op::Or, BinaryOperator::Kind::Logic},  // !a | b
};

}  // namespace

std::size_t count_nodes(const Expression& expr) {
  std::size_t count = 1;
  for (const Expression& operand : expr.operands)
    count += count_nodes(operand);
  return count;
}

std::optional<Expression> ExpressionLowering::lower(const ast::Expr& expr) {
  nodes_ = 0;
  return lower_node(expr);
}

std::optional<Expression> ExpressionLowering::lower_as(const ast::Expr& expr, Type wanted,
                                                       std::string_view what) {
  auto result = lower(expr);
  if (!result) return std::nullopt;
  const bool fits = result->type == wanted || (wanted == Type::Real && result->type == Type::Int);
  if (!fits) {
    diagnostics_.error(
        expr.range, std::string(what) + " must be " +
                        (wanted == Type::Real ? std::string("a number")
                                              : "of type " + std::string(model::describe(wanted))) +
                        ", not " + std::string(model::describe(result->type)));
    return std::nullopt;
  }
  return result;
}

std::optional<Expression> ExpressionLowering::lower_node(const ast::Expr& expr) {
  std::optional<Expression> result;
  switch (expr.kind) {
    case ast::Expr::Kind::Integer:
    case ast::Expr::Kind::Real:
    case ast::Expr::Kind::Bool:
      result = literal(expr);
      break;
    case ast::Expr::Kind::Name:
    case ast::Expr::Kind::Extension:  // the property language's nodes: its resolver's business
      result = resolve_(expr);
      if (result) {
        nodes_ += count_nodes(*result);
        result->range = expr.range;
      }
      break;
    case ast::Expr::Kind::Unary:
      result = unary(expr);
      break;
    case ast::Expr::Kind::Binary:
      result = binary(expr);
      break;
    case ast::Expr::Kind::IfThenElse:
      result = conditional(expr);
      break;
    case ast::Expr::Kind::Call:
      result = call(expr);
      break;
  }
  if (result && ++nodes_ > kMaxExpressionNodes) {
    diagnostics_.error(expr.range, "expression grows past " + std::to_string(kMaxExpressionNodes) +
                                       " nodes once its formulas are expanded");
    return std::nullopt;
  }
  return result;
}

std::optional<Expression> ExpressionLowering::literal(const ast::Expr& expr) {
  if (expr.kind == ast::Expr::Kind::Bool) {
    return Expression::make_constant(expr.text == "true" ? 1 : 0, Type::Bool, expr.range);
  }
  const std::optional<Rational> value = parse_decimal(expr.text);
  if (!value) {
    diagnostics_.error(expr.range, "cannot read the number " + quoted(expr.text));
    return std::nullopt;
  }
  if (bit_size(*value) > max_number_bits_) {
    diagnostics_.error(expr.range, too_long_message(*value, max_number_bits_));
    return std::nullopt;
  }
  return Expression::make_constant(
      *value, expr.kind == ast::Expr::Kind::Integer ? Type::Int : Type::Real, expr.range);
}

bool ExpressionLowering::check_operand(const Expression& operand, bool want_number,
                                       std::string_view op) {
  if (want_number ? numeric(operand.type) : operand.type == Type::Bool) return true;
  diagnostics_.error(operand.range, "operand of '" + std::string(op) + "' must be " +
                                        (want_number ? "a number" : "a boolean") + ", not " +
                                        std::string(model::describe(operand.type)));
  return false;
}

std::optional<Expression> ExpressionLowering::unary(const ast::Expr& expr) {
  auto operand = lower_node(expr.operands[0]);
  if (!operand) return std::nullopt;
  const bool negate = expr.text == "-";
  if (!check_operand(*operand, negate, expr.text)) return std::nullopt;
  const Type type = operand->type;
  return fold(make(negate ? Op::Negate : Op::Not, type, {std::move(*operand)}, expr.range));
}

std::optional<Expression> ExpressionLowering::binary(const ast::Expr& expr) {
  const auto* found =
      std::find_if(std::begin(kBinaryOperators), std::end(kBinaryOperators),
                   [&](const BinaryOperator& o) { return o.spelling == expr.text; });
  auto left = lower_node(expr.operands[0]);
  auto right = lower_node(expr.operands[1]);
  if (!left || !right) return std::nullopt;
  using Kind = BinaryOperator::Kind;
  Type type = Type::Bool;
  switch (found->kind) {
    case Kind::Arithmetic:
    case Kind::Division:
    case Kind::Comparison:
      if (!check_operand(*left, true, expr.text) || !check_operand(*right, true, expr.text))
        return std::nullopt;
      if (found->kind == Kind::Arithmetic)
        type = left->type == Type::Int && right->type == Type::Int ? Type::Int : Type::Real;
      if (found->kind == Kind::Division) type = Type::Real;
      break;
    case Kind::Equality:
      if (numeric(left->type) != numeric(right->type)) {
        diagnostics_.error(expr.range, "'" + expr.text + "' compares a " +
                                           std::string(model::describe(left->type)) + " with a " +
                                           std::string(model::describe(right->type)));
        return std::nullopt;
      }
      break;
    case Kind::Logic:
      if (!check_operand(*left, false, expr.text) || !check_operand(*right, false, expr.text))
        return std::nullopt;
      if (expr.text == "=>") left = make(Op::Not, Type::Bool, {std::move(*left)}, expr.range);
      break;
  }
  return fold(make(found->op, type, {std::move(*left), std::move(*right)}, expr.range));
}

std::optional<Expression> ExpressionLowering::conditional(const ast::Expr& expr) {
  auto condition = lower_node(expr.operands[0]);
  auto then = lower_node(expr.operands[1]);
  auto otherwise = lower_node(expr.operands[2]);
  if (!condition || !then || !otherwise) return std::nullopt;
  if (!check_operand(*condition, false, "?")) return std::nullopt;
  Type type = then->type;
  if (then->type != otherwise->type) {
    if (!numeric(then->type) || !numeric(otherwise->type)) {
      diagnostics_.error(expr.range, "the branches of '? :' are a " +
                                         std::string(model::describe(then->type)) + " and a " +
                                         std::string(model::describe(otherwise->type)));
      return std::nullopt;
    }
    type = Type::Real;
  }
  return fold(make(Op::IfThenElse, type,
                   {std::move(*condition), std::move(*then), std::move(*otherwise)}, expr.range));
}

std::optional<Expression> ExpressionLowering::call(const ast::Expr& expr) {
  struct Function {
    std::string_view name;
    Op op;
    std::size_t min_args, max_args;
  };
  static constexpr Function kFunctions[] = {
      {"min", Op::Min, 2, 64},  {"max", Op::Max, 2, 64},  {"floor", Op::Floor, 1, 1},
      {"ceil", Op::Ceil, 1, 1}, {"pow", Op::Power, 2, 2}, {"mod", Op::ModPositive, 2, 2},
  };
  const auto* found = std::find_if(std::begin(kFunctions), std::end(kFunctions),
                                   [&](const Function& f) { return f.name == expr.text; });
  if (found == std::end(kFunctions)) {
    diagnostics_.error(expr.range, "unknown function " + quoted(expr.text) +
                                       " (oasis has min, max, floor, ceil, pow and mod)");
    return std::nullopt;
  }
  if (expr.operands.size() < found->min_args || expr.operands.size() > found->max_args) {
    diagnostics_.error(expr.range, quoted(expr.text) + " takes " +
                                       (found->min_args == found->max_args
                                            ? std::to_string(found->min_args)
                                            : "at least " + std::to_string(found->min_args)) +
                                       " arguments, not " + std::to_string(expr.operands.size()));
    return std::nullopt;
  }
  std::vector<Expression> operands;
  Type type = Type::Int;
  for (const ast::Expr& operand : expr.operands) {
    auto lowered = lower_node(operand);
    if (!lowered) return std::nullopt;
    if (!check_operand(*lowered, true, expr.text)) return std::nullopt;
    if (lowered->type == Type::Real) type = Type::Real;
    operands.push_back(std::move(*lowered));
  }
  if (found->op == Op::Floor || found->op == Op::Ceil) type = Type::Int;
  if (found->op == Op::Power) type = operands[0].type;
  if ((found->op == Op::ModPositive || found->op == Op::Power) && operands[1].type != Type::Int) {
    diagnostics_.error(operands[1].range, "the second argument of " + quoted(expr.text) +
                                              " must be an int (oasis computes exactly)");
    return std::nullopt;
  }
  if (found->op == Op::ModPositive && operands[0].type != Type::Int) {
    diagnostics_.error(operands[0].range, "the arguments of 'mod' must be ints");
    return std::nullopt;
  }
  return fold(make(found->op, type, std::move(operands), expr.range));
}

// Evaluates an expression whose operands are all constants, once, here.
std::optional<Expression> ExpressionLowering::fold(Expression expr) {
  const bool constant = std::all_of(expr.operands.begin(), expr.operands.end(),
                                    [](const Expression& e) { return e.is_constant(); });
  if (!constant) return expr;
  try {
    Rational value;
    if (expr.type == Type::Bool) {
      value = model::evaluate_bool(expr, {}) ? 1 : 0;
    } else {
      value = model::evaluate_number(expr, {});
    }
    if (bit_size(value) > max_number_bits_) {
      diagnostics_.error(expr.range, too_long_message(value, max_number_bits_));
      return std::nullopt;
    }
    return Expression::make_constant(std::move(value), expr.type, expr.range);
  } catch (const model::EvaluationError& error) {
    diagnostics_.error(error.where, error.what());
    return std::nullopt;
  }
}

}  // namespace oasis::prism
