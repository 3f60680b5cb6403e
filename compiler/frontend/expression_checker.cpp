#include "frontend/expression_checker.hpp"

#include <array>
#include <string>
#include <utility>

#include "support/double_range.hpp"
#include "support/text.hpp"

namespace oasis::frontend {
namespace {

using model::Expression;
using model::Op;
using model::Type;

bool is_numeric(Type type) {
  return type == Type::Int || type == Type::Real;
}

Op binary_op(TokenKind kind) {
  switch (kind) {
    case TokenKind::Plus:
      return Op::Add;
    case TokenKind::Minus:
      return Op::Subtract;
    case TokenKind::Star:
      return Op::Multiply;
    case TokenKind::Slash:
      return Op::Divide;
    case TokenKind::Caret:
      return Op::Power;
    case TokenKind::Equal:
      return Op::Equal;
    case TokenKind::NotEqual:
      return Op::NotEqual;
    case TokenKind::Less:
      return Op::Less;
    case TokenKind::LessEqual:
      return Op::LessEqual;
    case TokenKind::Greater:
      return Op::Greater;
    case TokenKind::GreaterEqual:
      return Op::GreaterEqual;
    case TokenKind::And:
      return Op::And;
    default:
      return Op::Or;
  }
}

struct Builtin {
  std::string_view name;
  Op op;
  std::size_t min_args;
  std::size_t max_args;
  bool dynamics_only = false;  // not rational-valued: allowed in dynamics, never folded
};

constexpr std::array kBuiltins = {
    Builtin{"min", Op::Min, 1, 16},        Builtin{"max", Op::Max, 1, 16},
    Builtin{"floor", Op::Floor, 1, 1},     Builtin{"ceil", Op::Ceil, 1, 1},
    Builtin{"abs", Op::Abs, 1, 1},         Builtin{"mod", Op::Mod, 2, 2},
    Builtin{"pow", Op::Power, 2, 2},       Builtin{"sin", Op::Sin, 1, 1, true},
    Builtin{"cos", Op::Cos, 1, 1, true},   Builtin{"tan", Op::Tan, 1, 1, true},
    Builtin{"atan", Op::Atan, 1, 1, true}, Builtin{"exp", Op::Exp, 1, 1, true},
    Builtin{"log", Op::Log, 1, 1, true},   Builtin{"sqrt", Op::Sqrt, 1, 1, true},
};

bool is_irrational_function(Op op) {
  return op == Op::Sin || op == Op::Cos || op == Op::Tan || op == Op::Atan || op == Op::Exp ||
         op == Op::Log || op == Op::Sqrt;
}

// "a bool", "an int", "a number".
std::string with_article(Type type) {
  return std::string(type == Type::Int ? "an " : "a ") + std::string(model::describe(type));
}

}  // namespace

std::string_view describe(SymbolKind kind) {
  switch (kind) {
    case SymbolKind::Constant:
      return "constant";
    case SymbolKind::Variable:
      return "variable";
    case SymbolKind::ContinuousVariable:
      return "continuous variable";
    case SymbolKind::State:
      return "state";
    case SymbolKind::Region:
      return "region";
    case SymbolKind::Input:
      return "input";
  }
  return "name";
}

std::optional<Expression> ExpressionChecker::check(const ast::Expr& expr,
                                                   const ExpressionRules& rules) {
  switch (expr.kind) {
    case ast::ExprKind::Number: {
      auto value = parse_decimal(expr.text);
      if (!value) {
        diagnostics_.error(expr.range, "number " + quoted(expr.text) + " is out of range");
        return std::nullopt;
      }
      if (const std::size_t bits = bit_size(*value); bits > max_number_bits_) {
        const std::string subject = "number of " + std::to_string(expr.text.size()) + " characters";
        diagnostics_.error(expr.range, too_long_message(subject, bits, max_number_bits_));
        return std::nullopt;
      }
      const bool integer = expr.text.find_first_of(".eE") == std::string_view::npos;
      return Expression::make_constant(std::move(*value), integer ? Type::Int : Type::Real,
                                       expr.range);
    }
    case ast::ExprKind::Boolean:
      return Expression::make_constant(Rational(expr.text == "true" ? 1 : 0), Type::Bool,
                                       expr.range);
    case ast::ExprKind::Name:
      return name(expr, rules);
    case ast::ExprKind::Unary:
      return unary(expr, rules);
    case ast::ExprKind::Binary:
      return binary(expr, rules);
    case ast::ExprKind::Call:
      return call(expr, rules);
  }
  return std::nullopt;
}

std::optional<Expression> ExpressionChecker::name(const ast::Expr& expr,
                                                  const ExpressionRules& rules) {
  const auto* entry = scope_.find(expr.text);
  if (entry == nullptr) {
    diagnostics_.error(expr.range, "unknown name " + quoted(expr.text));
    return std::nullopt;
  }
  const Symbol& symbol = entry->value;
  if (symbol.failed) return std::nullopt;  // its definition's error was reported
  auto refuse = [&] {
    diagnostics_.error(expr.range, std::string(describe(symbol.kind)) + " " + quoted(expr.text) +
                                       " cannot be used " + std::string(rules.place));
    return std::nullopt;
  };
  Expression result;
  result.range = expr.range;
  result.type = symbol.type;
  result.slot = symbol.index;
  switch (symbol.kind) {
    case SymbolKind::Constant:
      return Expression::make_constant(symbol.value, symbol.type, expr.range);
    case SymbolKind::Variable:
      if (!rules.discrete_state) return refuse();
      result.op = Op::Variable;
      return result;
    case SymbolKind::State:
      if (!rules.discrete_state) return refuse();
      result.op = Op::StateIs;
      return result;
    case SymbolKind::ContinuousVariable:
      if (!rules.continuous) return refuse();
      result.op = Op::ContinuousVariable;
      return result;
    case SymbolKind::Input:
      if (!rules.dynamics) return refuse();
      result.op = Op::InputVariable;
      return result;
    case SymbolKind::Region:
      if (!rules.regions) return refuse();
      result.op = Op::RegionIs;
      return result;
  }
  return std::nullopt;
}

bool ExpressionChecker::expect_type(const Expression& expr, Type type, std::string_view context) {
  const bool ok = type == Type::Real ? is_numeric(expr.type) : expr.type == type;
  if (!ok) {
    diagnostics_.error(expr.range, std::string(context) + " needs " + with_article(type) +
                                       ", not " + with_article(expr.type));
  }
  return ok;
}

std::optional<Expression> ExpressionChecker::unary(const ast::Expr& expr,
                                                   const ExpressionRules& rules) {
  auto operand = check(*expr.operands[0], rules);
  if (!operand) return std::nullopt;
  Expression result;
  result.range = expr.range;
  if (expr.op == TokenKind::Not) {
    if (!expect_type(*operand, Type::Bool, "'!'")) return std::nullopt;
    result.op = Op::Not;
    result.type = Type::Bool;
  } else {
    if (!expect_type(*operand, Type::Real, "'-'")) return std::nullopt;
    result.op = Op::Negate;
    result.type = operand->type;
  }
  result.operands.push_back(std::move(*operand));
  return fold(std::move(result));
}

std::optional<Expression> ExpressionChecker::binary(const ast::Expr& expr,
                                                    const ExpressionRules& rules) {
  auto left = check(*expr.operands[0], rules);
  auto right = check(*expr.operands[1], rules);
  if (!left || !right) return std::nullopt;
  Expression result;
  result.op = binary_op(expr.op);
  result.range = expr.range;
  const std::string op_name = quoted(describe(expr.op).substr(1, describe(expr.op).size() - 2));
  switch (result.op) {
    case Op::And:
    case Op::Or:
      if (!expect_type(*left, Type::Bool, op_name) || !expect_type(*right, Type::Bool, op_name)) {
        return std::nullopt;
      }
      result.type = Type::Bool;
      break;
    case Op::Equal:
    case Op::NotEqual:
      if (left->type == Type::Bool || right->type == Type::Bool) {
        if (!expect_type(*left, Type::Bool, op_name) || !expect_type(*right, Type::Bool, op_name)) {
          return std::nullopt;
        }
        result.type = Type::Bool;
        break;
      }
      [[fallthrough]];
    case Op::Less:
    case Op::LessEqual:
    case Op::Greater:
    case Op::GreaterEqual:
      if (!expect_type(*left, Type::Real, op_name) || !expect_type(*right, Type::Real, op_name)) {
        return std::nullopt;
      }
      result.type = Type::Bool;
      break;
    default:  // arithmetic
      if (!expect_type(*left, Type::Real, op_name) || !expect_type(*right, Type::Real, op_name)) {
        return std::nullopt;
      }
      result.type = result.op != Op::Divide && left->type == Type::Int && right->type == Type::Int
                        ? Type::Int
                        : Type::Real;
      break;
  }
  result.operands.push_back(std::move(*left));
  result.operands.push_back(std::move(*right));
  if (result.op == Op::Power) return power(std::move(result));
  return fold(std::move(result));
}

std::optional<Expression> ExpressionChecker::call(const ast::Expr& expr,
                                                  const ExpressionRules& rules) {
  const Builtin* builtin = nullptr;
  for (const Builtin& candidate : kBuiltins) {
    if (candidate.name == expr.text) builtin = &candidate;
  }
  if (builtin == nullptr) {
    diagnostics_.error(SourceRange{expr.range.begin, static_cast<std::uint32_t>(expr.text.size())},
                       "unknown function " + quoted(expr.text) +
                           " (functions are min, max, floor, ceil, abs, mod, pow; in dynamics "
                           "also sin, cos, tan, atan, exp, log, sqrt)");
    return std::nullopt;
  }
  if (expr.operands.size() < builtin->min_args || expr.operands.size() > builtin->max_args) {
    diagnostics_.error(expr.range, "wrong number of arguments to " + quoted(expr.text));
    return std::nullopt;
  }
  if (builtin->dynamics_only && !rules.dynamics) {
    diagnostics_.error(expr.range, quoted(expr.text) +
                                       " is allowed only in dynamics (its values "
                                       "are not exact rationals)");
    return std::nullopt;
  }
  Expression result;
  result.op = builtin->op;
  result.range = expr.range;
  result.type = Type::Int;
  for (const auto& operand : expr.operands) {
    auto checked = check(*operand, rules);
    if (!checked || !expect_type(*checked, Type::Real, quoted(expr.text))) return std::nullopt;
    if (checked->type == Type::Real) result.type = Type::Real;
    result.operands.push_back(std::move(*checked));
  }
  if (result.op == Op::Floor || result.op == Op::Ceil) result.type = Type::Int;
  if (builtin->dynamics_only) result.type = Type::Real;
  if (result.op == Op::Power) return power(std::move(result));
  if (result.op == Op::Mod && result.type != Type::Int) {
    diagnostics_.error(expr.range, "'mod' needs integer arguments");
    return std::nullopt;
  }
  return fold(std::move(result));
}

// `a ^ n` and `pow(a, n)`: n an integer constant of at most 64 in size, so that folding stays
// small and interval powers (geom) stay exact in their shape. Int ^ non-negative int is an Int.
std::optional<Expression> ExpressionChecker::power(Expression expr) {
  const Expression& exponent = expr.operands[1];
  if (!exponent.is_constant() || exponent.constant.get_den() != 1 || abs(exponent.constant) > 64) {
    diagnostics_.error(exponent.range, "the exponent must be an integer constant from -64 to 64");
    return std::nullopt;
  }
  expr.type = expr.operands[0].type == Type::Int && exponent.constant >= 0 ? Type::Int : Type::Real;
  return fold(std::move(expr));
}

// Evaluates an operation whose operands are all constants; the evaluator's errors (division
// by zero, overflow) become diagnostics at the expression.
std::optional<Expression> ExpressionChecker::fold(Expression expr) {
  if (is_irrational_function(expr.op)) return expr;
  for (const Expression& operand : expr.operands) {
    if (!operand.is_constant()) return expr;
  }
  try {
    Rational value;
    if (expr.type == Type::Bool) {
      value = model::evaluate_bool(expr, {}) ? 1 : 0;
    } else if (expr.type == Type::Int) {
      value = Rational(model::evaluate_int(expr, {}));
    } else {
      value = model::evaluate_number(expr, {});
    }
    if (!check_number_size(value, expr.range)) return std::nullopt;
    return Expression::make_constant(std::move(value), expr.type, expr.range);
  } catch (const model::EvaluationError& error) {
    diagnostics_.error(error.where, error.what());
    return std::nullopt;
  }
}

bool ExpressionChecker::check_number_size(const Rational& value, SourceRange where) {
  if (bit_size(value) <= max_number_bits_) return true;
  diagnostics_.error(where, "number " + too_long_message(value, max_number_bits_));
  return false;
}

std::optional<Expression> ExpressionChecker::check_typed(const ast::Expr& expr,
                                                         const ExpressionRules& rules, Type type,
                                                         std::string_view what) {
  auto checked = check(expr, rules);
  if (!checked || !expect_type(*checked, type, what)) return std::nullopt;
  return checked;
}

std::optional<Rational> ExpressionChecker::constant_value(const ast::Expr& expr,
                                                          std::string_view what) {
  const ExpressionRules rules{.place = "in a constant expression"};
  auto checked = check_typed(expr, rules, Type::Real, what);
  if (!checked) return std::nullopt;
  return checked->constant;
}

std::optional<Rational> ExpressionChecker::constant_number(const ast::Expr& expr,
                                                           std::string_view what) {
  auto value = constant_value(expr, what);
  if (!value || !check_carried_value(*value, what, expr.range, diagnostics_)) return std::nullopt;
  return value;
}

// Integers (horizons, ranges of discrete variables) are not carried as doubles: only their
// own bounds apply.
std::optional<std::int64_t> ExpressionChecker::constant_integer(const ast::Expr& expr,
                                                                std::string_view what) {
  auto value = constant_value(expr, what);
  if (!value) return std::nullopt;
  if (value->get_den() != 1 || !value->get_num().fits_slong_p()) {
    diagnostics_.error(
        expr.range,
        std::string(what) + " must be an integer that fits in 64 bits, not " + describe(*value));
    return std::nullopt;
  }
  return value->get_num().get_si();
}

std::optional<Rational> ExpressionChecker::branch_probability(const ast::Branch& branch) {
  if (!branch.probability) return Rational(1);
  std::optional<Rational> p = constant_number(*branch.probability, "a probability");
  if (!p) return std::nullopt;
  if (*p < 0 || *p > 1) {
    diagnostics_.error(
        branch.probability->range,
        "probability " + describe(*p) + (*p < 0 ? " is negative" : " is greater than 1"));
    return std::nullopt;
  }
  return p;
}

std::optional<model::Expression> declare_constant(const ast::ConstDecl& constant, Scope& scope,
                                                  ExpressionChecker& expressions,
                                                  DiagnosticEngine& diagnostics) {
  auto value = expressions.check(*constant.value, ExpressionRules{.place = "in a constant"});
  if (value && !value->is_constant()) {
    diagnostics.error(constant.value->range, "constant " + quoted(constant.name.text) +
                                                 " needs a value known before exploration");
    value.reset();
  }
  Symbol symbol{SymbolKind::Constant,
                0,
                value ? value->type : model::Type::Int,
                value ? value->constant : Rational(0),
                constant.name.range,
                !value};
  const bool fresh = scope.declare(constant.name.text, constant.name.range, std::move(symbol),
                                   "name", diagnostics);
  return fresh ? value : std::nullopt;
}

}  // namespace oasis::frontend
