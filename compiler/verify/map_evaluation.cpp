#include "verify/map_evaluation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "support/rational.hpp"

namespace oasis::verify {
namespace {

using model::Op;

[[noreturn]] void refuse(const std::string& message) {
  throw std::invalid_argument(message);
}

// The operations a map's coordinate may hold, and how many operands each takes (0: any
// number from one up, folded left to right).
int arity(Op op) {
  switch (op) {
    case Op::Constant:
    case Op::ContinuousVariable:
    case Op::InputVariable:
      return 0;
    case Op::Negate:
    case Op::Abs:
    case Op::Sin:
    case Op::Cos:
    case Op::Tan:
    case Op::Atan:
    case Op::Exp:
    case Op::Log:
    case Op::Sqrt:
      return 1;
    case Op::Subtract:
    case Op::Divide:
    case Op::Power:
      return 2;
    case Op::Add:
    case Op::Multiply:
    case Op::Min:
    case Op::Max:
      return -1;
    default:
      return -2;  // not an operation of dynamics
  }
}

double apply_unary(Op op, double a) {
  switch (op) {
    case Op::Negate:
      return -a;
    case Op::Abs:
      return std::fabs(a);
    case Op::Sin:
      return std::sin(a);
    case Op::Cos:
      return std::cos(a);
    case Op::Tan:
      return std::tan(a);
    case Op::Atan:
      return std::atan(a);
    case Op::Exp:
      return std::exp(a);
    case Op::Log:
      return std::log(a);
    default:  // Op::Sqrt: compile() admits no other unary operation
      return std::sqrt(a);
  }
}

double apply_binary(Op op, double a, double b) {
  switch (op) {
    case Op::Add:
      return a + b;
    case Op::Subtract:
      return a - b;
    case Op::Multiply:
      return a * b;
    case Op::Divide:
      return a / b;
    case Op::Min:
      return std::min(a, b);
    default:  // Op::Max
      return std::max(a, b);
  }
}

// The exponent of `a ^ n`: the front end admits integer constants only (docs/guarantees.md).
std::int64_t exponent_of(const model::Expression& exponent) {
  if (exponent.op != Op::Constant || exponent.constant.get_den() != 1 ||
      !exponent.constant.get_num().fits_slong_p())
    refuse("a power whose exponent is not an integer constant");
  return exponent.constant.get_num().get_si();
}

}  // namespace

double integer_power(double base, std::int64_t exponent) {
  // The magnitude as unsigned: -INT64_MIN does not fit in int64_t.
  std::uint64_t n = exponent < 0 ? 0 - static_cast<std::uint64_t>(exponent)
                                 : static_cast<std::uint64_t>(exponent);
  double result = 1;
  for (double square = base; n != 0; n >>= 1, square *= square)
    if ((n & 1) != 0) result *= square;
  return exponent < 0 ? 1 / result : result;
}

DoubleProgram DoubleProgram::compile(const model::Expression& expr, std::size_t state_size,
                                     std::size_t input_size) {
  DoubleProgram program;
  program.state_size_ = state_size;
  program.input_size_ = input_size;
  program.emit(expr, 0);
  return program;
}

// Appends the steps of `expr`, evaluated with `depth` values already on the stack.
void DoubleProgram::emit(const model::Expression& expr, std::size_t depth) {
  const int expected = arity(expr.op);
  const std::size_t operands = expr.operands.size();
  if (expected == -2)
    refuse("an operation dynamics do not hold (operation " +
           std::to_string(static_cast<int>(expr.op)) + ")");
  if ((expected >= 0 && operands != static_cast<std::size_t>(expected)) ||
      (expected == -1 && operands == 0))
    refuse("an operation with " + std::to_string(operands) + " operands");
  Step step{.op = expr.op, .operand = static_cast<std::uint32_t>(operands)};
  if (expr.op == Op::Constant) step.value = to_double(expr.constant);
  if (expr.op == Op::ContinuousVariable || expr.op == Op::InputVariable) {
    const std::size_t size = expr.op == Op::InputVariable ? input_size_ : state_size_;
    if (expr.slot >= size) refuse("a variable or input slot out of range");
    step.operand = expr.slot;
  }
  if (expr.op == Op::Power) {
    step.exponent = exponent_of(expr.operands[1]);
    emit(expr.operands[0], depth);  // the exponent is in the step, not on the stack
  } else {
    for (std::size_t i = 0; i < operands; ++i)
      emit(expr.operands[i], depth + i);
  }
  stack_size_ = std::max(stack_size_, depth + 1);
  steps_.push_back(step);
}

double DoubleProgram::evaluate(std::span<const double> state,
                               std::span<const double> inputs) const {
  // Dynamics are short expressions: a stack on the machine's stack, a vector past that.
  constexpr std::size_t kLocal = 32;
  std::array<double, kLocal> local{};
  std::vector<double> heap;
  double* stack = local.data();
  if (stack_size_ > kLocal) {
    heap.resize(stack_size_);
    stack = heap.data();
  }
  std::size_t top = 0;  // values on the stack
  for (const Step& step : steps_) {
    switch (step.op) {
      case Op::Constant:
        stack[top++] = step.value;
        break;
      case Op::ContinuousVariable:
        stack[top++] = state[step.operand];
        break;
      case Op::InputVariable:
        stack[top++] = inputs[step.operand];
        break;
      case Op::Power:
        stack[top - 1] = integer_power(stack[top - 1], step.exponent);
        break;
      case Op::Subtract:
      case Op::Divide:
      case Op::Add:
      case Op::Multiply:
      case Op::Min:
      case Op::Max: {
        // n operands: fold left to right, as the expression reads.
        const std::size_t first = top - step.operand;
        double value = stack[first];
        for (std::size_t i = first + 1; i < top; ++i)
          value = apply_binary(step.op, value, stack[i]);
        top = first;
        stack[top++] = value;
        break;
      }
      default:
        stack[top - 1] = apply_unary(step.op, stack[top - 1]);
        break;
    }
  }
  return stack[0];
}

}  // namespace oasis::verify
