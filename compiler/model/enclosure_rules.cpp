#include "model/enclosure_rules.hpp"

#include <string>

#include "model/enclosure.hpp"

namespace oasis::model::enclosure_rules {

bool is_leaf(Op op) {
  return op == Op::Constant || op == Op::ContinuousVariable || op == Op::InputVariable;
}

bool is_unary(Op op) {
  switch (op) {
    case Op::Negate:
    case Op::Abs:
    case Op::Sin:
    case Op::Cos:
    case Op::Tan:
    case Op::Atan:
    case Op::Exp:
    case Op::Log:
    case Op::Sqrt:
      return true;
    default:
      return false;
  }
}

bool is_binary(Op op) {
  switch (op) {
    case Op::Add:
    case Op::Subtract:
    case Op::Multiply:
    case Op::Divide:
    case Op::Min:
    case Op::Max:
      return true;
    default:
      return false;
  }
}

bool is_allowed(Op op) {
  return is_leaf(op) || is_unary(op) || is_binary(op) || op == Op::Power;
}

std::string_view disallowed_name(Op op) {
  switch (op) {
    case Op::Variable:
      return "a discrete variable";
    case Op::StateIs:
      return "a state test";
    case Op::RegionIs:
      return "a region";
    case Op::Floor:
      return "floor";
    case Op::Ceil:
      return "ceil";
    case Op::Mod:
    case Op::ModPositive:
      return "mod";
    case Op::IfThenElse:
      return "a conditional (c ? a : b)";
    case Op::Not:
    case Op::And:
    case Op::Or:
      return "a boolean operator";
    default:
      return "a comparison";
  }
}

const Expression& operand(const Expression& f, std::size_t i) {
  if (i >= f.operands.size())
    throw std::invalid_argument("a malformed expression: an operand is missing");
  return f.operands[i];
}

// The checker folds constant expressions, so an exponent that is not a constant is refused.
std::int64_t exponent(const Expression& power_node) {
  const Expression& e = operand(power_node, 1);
  Rational n = e.constant;
  n.canonicalize();
  if (e.op != Op::Constant || n.get_den() != 1 || !n.get_num().fits_slong_p()) {
    throw EnclosureError(e.range, "the exponent must be an integer constant here");
  }
  return n.get_num().get_si();
}

Interval unary(Op op, Interval x) {
  switch (op) {
    case Op::Negate:
      return -x;
    case Op::Abs:
      return abs(x);
    case Op::Sin:
      return sin(x);
    case Op::Cos:
      return cos(x);
    case Op::Tan:
      return tan(x);
    case Op::Atan:
      return atan(x);
    case Op::Exp:
      return exp(x);
    case Op::Log:
      return log(x);
    default:
      return sqrt(x);
  }
}

Interval binary(Op op, Interval x, Interval y) {
  switch (op) {
    case Op::Add:
      return x + y;
    case Op::Subtract:
      return x - y;
    case Op::Multiply:
      return x * y;
    case Op::Divide:
      return x / y;
    case Op::Min:
      return min(x, y);
    default:
      return max(x, y);
  }
}

Interval unary_derivative(Op op, Interval x, Interval value) {
  switch (op) {
    case Op::Negate:
      return {-1, -1};
    case Op::Abs:  // at a kink inside x, either side's slope
      if (x.lo >= 0) return kOne;
      if (x.hi <= 0) return {-1, -1};
      return {-1, 1};
    case Op::Sin:
      return cos(x);
    case Op::Cos:
      return -sin(x);
    case Op::Tan:
      return kOne + power(value, 2);
    case Op::Atan:
      return kOne / (kOne + power(x, 2));
    case Op::Exp:
      return value;
    case Op::Log:
      return kOne / x;
    default:  // sqrt: 1 / (2 sqrt(x)), refused where sqrt(x) reaches 0
      return kOne / (Interval{2, 2} * value);
  }
}

}  // namespace oasis::model::enclosure_rules
