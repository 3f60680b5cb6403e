#pragma once
// The verifier's own evaluation of a continuous model's map x' = f(x, u) in doubles, for the
// Monte-Carlo check of a controller (controller_check.hpp). It shares nothing with the
// compiler's interval enclosures (model/enclosure.hpp): it reads the model IR's expression and
// evaluates it the plain way, each operation rounded to nearest by the machine.
//
// An expression is compiled once into a postfix program (constants already doubles, an
// integer power's exponent already read), so that the millions of evaluations of a check walk
// a flat array instead of a tree of Rationals.

#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <vector>

#include "model/expression.hpp"

namespace oasis::verify {

class DoubleProgram {
 public:
  // Compiles `expr`, an expression of dynamics over `state_size` continuous variables and
  // `input_size` inputs. Throws std::invalid_argument (one sentence) for an operation dynamics
  // never hold (a comparison, a discrete variable), a power whose exponent is not an integer
  // constant, or a slot out of range.
  static DoubleProgram compile(const model::Expression& expr, std::size_t state_size,
                               std::size_t input_size);

  // f(state, inputs), with `state` and `inputs` of the sizes given to compile().
  [[nodiscard]] double evaluate(std::span<const double> state,
                                std::span<const double> inputs) const;

 private:
  struct Step {
    model::Op op = model::Op::Constant;
    std::uint32_t operand = 0;  // a variable's or input's slot, or an n-ary operation's arity
    double value = 0;           // Constant
    std::int64_t exponent = 0;  // Power
  };
  void emit(const model::Expression& expr, std::size_t depth);

  std::vector<Step> steps_;
  std::size_t stack_size_ = 0;  // the deepest the evaluation stack gets
  std::size_t state_size_ = 0;
  std::size_t input_size_ = 0;
};

// base^exponent by repeated squaring: x^2 is x * x exactly as written out.
double integer_power(double base, std::int64_t exponent);

}  // namespace oasis::verify
