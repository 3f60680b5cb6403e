#include "model/expression.hpp"

#include <algorithm>
#include <string>
#include <utility>

namespace oasis::model {
namespace {

[[noreturn]] void overflow(const Expression& expr) {
  throw EvaluationError(expr.range, "integer overflow (values must fit in 64 bits)");
}

// Integer operations with overflow detection. (The result must be read after the builtin
// has written it, so it is not passed alongside the builtin's call as an argument.)
template <typename Operation>
std::int64_t checked(const Expression& expr, Operation operation, std::int64_t a, std::int64_t b) {
  std::int64_t result = 0;
  if (operation(a, b, &result)) overflow(expr);
  return result;
}

bool add(std::int64_t a, std::int64_t b, std::int64_t* r) {
  return __builtin_add_overflow(a, b, r);
}
bool subtract(std::int64_t a, std::int64_t b, std::int64_t* r) {
  return __builtin_sub_overflow(a, b, r);
}
bool multiply(std::int64_t a, std::int64_t b, std::int64_t* r) {
  return __builtin_mul_overflow(a, b, r);
}

// Comparison for int64 and exact rationals alike.
template <typename Number>
bool compare(Op op, const Number& a, const Number& b) {
  switch (op) {
    case Op::Equal:
      return a == b;
    case Op::NotEqual:
      return a != b;
    case Op::Less:
      return a < b;
    case Op::LessEqual:
      return a <= b;
    case Op::Greater:
      return a > b;
    case Op::GreaterEqual:
      return a >= b;
    default:
      return false;
  }
}

std::int64_t to_int64(const Expression& expr, const Rational& value) {
  if (value.get_den() != 1) {
    throw EvaluationError(expr.range, "value " + describe(value) + " is not an integer");
  }
  if (!value.get_num().fits_slong_p()) overflow(expr);
  return value.get_num().get_si();
}

// base^exponent by repeated squaring, every product checked.
std::int64_t int_power(const Expression& expr, std::int64_t base, std::int64_t exponent) {
  if (exponent < 0) {
    throw EvaluationError(expr.range, "integer power with the negative exponent " +
                                          std::to_string(exponent) + " (write a real base)");
  }
  std::int64_t result = 1;
  while (exponent > 0) {
    if ((exponent & 1) != 0) result = checked(expr, multiply, result, base);
    exponent >>= 1;
    if (exponent > 0) base = checked(expr, multiply, base, base);
  }
  return result;
}

// Exact powers need an integer exponent; a huge one would build a huge number, so the
// exponent is bounded (the number-size limit bounds the rest where results are checked).
Rational rational_power(const Expression& expr, const Rational& base, std::int64_t exponent) {
  constexpr std::int64_t kMaxExponent = 4096;
  if (exponent > kMaxExponent || exponent < -kMaxExponent) {
    throw EvaluationError(expr.range, "exponent " + std::to_string(exponent) +
                                          " is too large for an exact power (at most " +
                                          std::to_string(kMaxExponent) + ")");
  }
  if (base == 0 && exponent < 0) throw EvaluationError(expr.range, "division by zero");
  const auto magnitude = static_cast<unsigned long>(exponent < 0 ? -exponent : exponent);
  constexpr std::size_t kMaxResultBits = std::size_t{1} << 24;
  if (bit_size(base) * magnitude > kMaxResultBits) {
    throw EvaluationError(expr.range, "power too large to compute exactly (more than " +
                                          std::to_string(kMaxResultBits) + " bits)");
  }
  Rational result;
  mpz_pow_ui(result.get_num_mpz_t(), base.get_num_mpz_t(), magnitude);
  mpz_pow_ui(result.get_den_mpz_t(), base.get_den_mpz_t(), magnitude);
  result.canonicalize();
  return exponent < 0 ? Rational(1 / result) : result;
}

}  // namespace

std::string_view describe(Type type) {
  switch (type) {
    case Type::Bool:
      return "bool";
    case Type::Int:
      return "int";
    case Type::Real:
      return "number";
  }
  return "?";
}

bool Expression::depends_on_state() const {
  if (op == Op::Variable || op == Op::StateIs) return true;
  return std::any_of(operands.begin(), operands.end(),
                     [](const Expression& e) { return e.depends_on_state(); });
}

Expression Expression::make_constant(Rational value, Type type, SourceRange range) {
  Expression expr;
  expr.op = Op::Constant;
  expr.type = type;
  expr.constant = std::move(value);
  expr.is_small_integer = expr.constant.get_den() == 1 && expr.constant.get_num().fits_slong_p();
  expr.small_integer = expr.is_small_integer ? expr.constant.get_num().get_si() : 0;
  expr.range = range;
  return expr;
}

bool evaluate_bool(const Expression& expr, Valuation state) {
  const auto& args = expr.operands;
  switch (expr.op) {
    case Op::Constant:
      return expr.is_small_integer ? expr.small_integer != 0 : expr.constant != 0;
    case Op::StateIs:
      return state[0] == static_cast<std::int64_t>(expr.slot);
    case Op::Not:
      return !evaluate_bool(args[0], state);
    case Op::And:
      return evaluate_bool(args[0], state) && evaluate_bool(args[1], state);
    case Op::Or:
      return evaluate_bool(args[0], state) || evaluate_bool(args[1], state);
    case Op::IfThenElse:
      return evaluate_bool(args[evaluate_bool(args[0], state) ? 1 : 2], state);
    case Op::Equal:
    case Op::NotEqual:
      if (args[0].type == Type::Bool) {
        const bool same = evaluate_bool(args[0], state) == evaluate_bool(args[1], state);
        return expr.op == Op::Equal ? same : !same;
      }
      [[fallthrough]];
    case Op::Less:
    case Op::LessEqual:
    case Op::Greater:
    case Op::GreaterEqual:
      if (args[0].type == Type::Int && args[1].type == Type::Int) {
        return compare(expr.op, evaluate_int(args[0], state), evaluate_int(args[1], state));
      }
      return compare(expr.op, evaluate_number(args[0], state), evaluate_number(args[1], state));
    default:
      throw EvaluationError(expr.range, "expression cannot be evaluated over a discrete state");
  }
}

std::int64_t evaluate_int(const Expression& expr, Valuation state) {
  const auto& args = expr.operands;
  switch (expr.op) {
    case Op::Constant:
      return expr.is_small_integer ? expr.small_integer : to_int64(expr, expr.constant);
    case Op::Variable:
      return state[expr.slot];
    case Op::Negate:
      return checked(expr, subtract, 0, evaluate_int(args[0], state));
    case Op::Add:
      return checked(expr, add, evaluate_int(args[0], state), evaluate_int(args[1], state));
    case Op::Subtract:
      return checked(expr, subtract, evaluate_int(args[0], state), evaluate_int(args[1], state));
    case Op::Multiply:
      return checked(expr, multiply, evaluate_int(args[0], state), evaluate_int(args[1], state));
    case Op::Min:
    case Op::Max: {
      std::int64_t best = evaluate_int(args[0], state);
      for (std::size_t i = 1; i < args.size(); ++i) {
        const std::int64_t v = evaluate_int(args[i], state);
        best = expr.op == Op::Min ? std::min(best, v) : std::max(best, v);
      }
      return best;
    }
    case Op::Abs: {
      const std::int64_t v = evaluate_int(args[0], state);
      if (v == INT64_MIN) overflow(expr);
      return v < 0 ? -v : v;
    }
    case Op::Mod:
    case Op::ModPositive: {
      const std::int64_t a = evaluate_int(args[0], state);
      const std::int64_t b = evaluate_int(args[1], state);
      if (expr.op == Op::ModPositive && b <= 0) {
        throw EvaluationError(expr.range, "mod(" + std::to_string(a) + ", " + std::to_string(b) +
                                              "): the divisor must be positive");
      }
      if (b == 0) throw EvaluationError(expr.range, "mod by zero");
      if (b == -1) return 0;  // a % -1 would overflow for INT64_MIN
      // The result has the sign of b, like Python (PRISM refuses b <= 0: ModPositive). Adjusting
      // the truncated remainder cannot overflow (r and b have opposite signs); a - floor(a / b) * b
      // did, e.g. for mod(1, INT64_MIN), where floor(a / b) * b is 2^63.
      const std::int64_t r = a % b;
      return r != 0 && ((r < 0) != (b < 0)) ? r + b : r;
    }
    case Op::Power:
      return int_power(expr, evaluate_int(args[0], state), evaluate_int(args[1], state));
    case Op::IfThenElse:
      return evaluate_int(args[evaluate_bool(args[0], state) ? 1 : 2], state);
    case Op::Floor:
    case Op::Ceil: {
      const Rational v = evaluate_number(args[0], state);
      mpz_class q;
      if (expr.op == Op::Floor) {
        mpz_fdiv_q(q.get_mpz_t(), v.get_num_mpz_t(), v.get_den_mpz_t());
      } else {
        mpz_cdiv_q(q.get_mpz_t(), v.get_num_mpz_t(), v.get_den_mpz_t());
      }
      if (!q.fits_slong_p()) overflow(expr);
      return q.get_si();
    }
    default:
      return to_int64(expr, evaluate_number(expr, state));
  }
}

Rational evaluate_number(const Expression& expr, Valuation state) {
  const auto& args = expr.operands;
  if (expr.type == Type::Int && expr.op != Op::Constant) return Rational(evaluate_int(expr, state));
  switch (expr.op) {
    case Op::Constant:
      return expr.constant;
    case Op::Negate:
      return -evaluate_number(args[0], state);
    case Op::Add:
      return evaluate_number(args[0], state) + evaluate_number(args[1], state);
    case Op::Subtract:
      return evaluate_number(args[0], state) - evaluate_number(args[1], state);
    case Op::Multiply:
      return evaluate_number(args[0], state) * evaluate_number(args[1], state);
    case Op::Divide: {
      const Rational divisor = evaluate_number(args[1], state);
      if (divisor == 0) throw EvaluationError(expr.range, "division by zero");
      return evaluate_number(args[0], state) / divisor;
    }
    case Op::Min:
    case Op::Max: {
      Rational best = evaluate_number(args[0], state);
      for (std::size_t i = 1; i < args.size(); ++i) {
        Rational v = evaluate_number(args[i], state);
        if (expr.op == Op::Min ? v < best : v > best) best = std::move(v);
      }
      return best;
    }
    case Op::Abs:
      return abs(evaluate_number(args[0], state));
    case Op::Power:
      return rational_power(expr, evaluate_number(args[0], state), evaluate_int(args[1], state));
    case Op::IfThenElse:
      return evaluate_number(args[evaluate_bool(args[0], state) ? 1 : 2], state);
    default:
      throw EvaluationError(expr.range, "expression cannot be evaluated over a discrete state");
  }
}

}  // namespace oasis::model
