#pragma once
// Typed, name-resolved expressions of the model IR, and their evaluation over a state.
// Constant sub-expressions are folded by the checker, so what remains refers to variables.
// Integer arithmetic is exact 64-bit with overflow detection; `/` is exact rational division.

#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "support/diagnostics.hpp"
#include "support/rational.hpp"

namespace oasis::model {

enum class Type { Bool, Int, Real };

std::string_view describe(Type type);
using oasis::describe;  // keep describe(Rational) visible beside the overload above

enum class Op {
  Constant,            // `constant`
  Variable,            // discrete variable `slot`
  ContinuousVariable,  // continuous variable `slot` (not evaluable over discrete states)
  StateIs,             // explicit models: "the state is `slot`" (slot 0 holds the state index)
  RegionIs,            // continuous models: "the state lies in region `slot`"
  Negate,
  Not,
  Add,
  Subtract,
  Multiply,
  Divide,
  Equal,
  NotEqual,
  Less,
  LessEqual,
  Greater,
  GreaterEqual,
  And,
  Or,
  Min,
  Max,
  Floor,
  Ceil,
  Abs,
  Mod,
  ModPositive,  // Mod whose divisor must be positive, as PRISM's mod requires
  Power,        // int ^ non-negative int, or number ^ int (PRISM's pow)
  IfThenElse,   // operands: condition, then, else (PRISM's c ? a : b)
  // Continuous dynamics only (x' = f(x, u)): the input `slot` of the model's `input` list, and
  // the functions whose values are not rational. They are never folded and never evaluated
  // exactly; model/enclosure.hpp bounds them, the verifier evaluates them in doubles.
  InputVariable,
  Sin,
  Cos,
  Tan,
  Atan,
  Exp,
  Log,
  Sqrt,
};

struct Expression {
  Op op = Op::Constant;
  Type type = Type::Int;
  Rational constant;  // Op::Constant; booleans are 0 or 1
  // Op::Constant: the value as a 64-bit integer when it is one (make_constant sets both), so
  // that evaluating a guard over each explored state does not read the Rational.
  bool is_small_integer = true;
  std::int64_t small_integer = 0;
  std::uint32_t slot = 0;  // Variable, ContinuousVariable, StateIs, RegionIs, InputVariable
  std::vector<Expression> operands;
  SourceRange range;

  [[nodiscard]] bool is_constant() const { return op == Op::Constant; }
  // True when the expression mentions a discrete variable or explicit state.
  [[nodiscard]] bool depends_on_state() const;

  static Expression make_constant(Rational value, Type type, SourceRange range);
};

// Raised when evaluating over a particular state fails (overflow, division by zero, a
// non-integer where an integer is needed). The caller adds which state it was.
struct EvaluationError : std::runtime_error {
  EvaluationError(SourceRange location, const std::string& message)
      : std::runtime_error(message), where(location) {}
  SourceRange where;
};

// Evaluation over a valuation of the discrete variables (explicit models: {state index}).
using Valuation = std::span<const std::int64_t>;
bool evaluate_bool(const Expression& expr, Valuation state);
std::int64_t evaluate_int(const Expression& expr, Valuation state);
Rational evaluate_number(const Expression& expr, Valuation state);

}  // namespace oasis::model
