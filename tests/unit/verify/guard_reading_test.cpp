// The verifier reads reward guards by evaluation (verify/guard_reading.hpp), the compiler
// symbolically (model/affine.hpp). On random guards over three variables, both readings must
// agree: the same constraints, or both refuse. A disagreement is a bug in one of them.

#include "verify/guard_reading.hpp"

#include <cstdlib>
#include <optional>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "model/affine.hpp"

namespace oasis {
namespace {

using model::Expression;
using model::Op;

constexpr std::size_t kVariables = 3;

Expression constant(Rational value) {
  return Expression::make_constant(std::move(value), model::Type::Real, {});
}

Rational fraction(int numerator, int denominator) {
  Rational value(numerator, denominator);
  value.canonicalize();
  return value;
}

Expression variable(std::uint32_t slot) {
  Expression e;
  e.op = Op::ContinuousVariable;
  e.type = model::Type::Real;
  e.slot = slot;
  return e;
}

Expression node(Op op, std::vector<Expression> operands) {
  Expression e;
  e.op = op;
  e.type = model::Type::Real;
  e.operands = std::move(operands);
  return e;
}

// A random arithmetic expression: mostly affine, sometimes a product of variables, a division
// by a variable or by zero, or a function the readings refuse.
Expression random_side(std::mt19937& random, int depth) {
  std::uniform_int_distribution<int> pick(0, depth <= 0 ? 1 : 9);
  std::uniform_int_distribution<int> small(-4, 4);
  switch (pick(random)) {
    case 0:
      return constant(fraction(small(random), 1 + std::abs(small(random))));
    case 1:
      return variable(static_cast<std::uint32_t>(random() % kVariables));
    case 2:
      return node(Op::Negate, {random_side(random, depth - 1)});
    case 3:
    case 4:
      return node(Op::Add, {random_side(random, depth - 1), random_side(random, depth - 1)});
    case 5:
      return node(Op::Subtract, {random_side(random, depth - 1), random_side(random, depth - 1)});
    case 6:
    case 7:
      return node(Op::Multiply, {random_side(random, depth - 1), random_side(random, depth - 1)});
    case 8:
      return node(Op::Divide, {random_side(random, depth - 1), random_side(random, depth - 1)});
    default:
      return node(Op::Abs, {random_side(random, depth - 1)});
  }
}

Expression random_guard(std::mt19937& random, int depth) {
  static const Op kComparisons[] = {Op::Less,         Op::LessEqual, Op::Greater,
                                    Op::GreaterEqual, Op::Equal,     Op::NotEqual};
  std::uniform_int_distribution<int> pick(0, depth <= 0 ? 1 : 5);
  Expression e;
  switch (pick(random)) {
    case 0:
    case 1:
      e = node(kComparisons[random() % 6], {random_side(random, 2), random_side(random, 2)});
      break;
    case 2:
    case 3:
      e = node(Op::And, {random_guard(random, depth - 1), random_guard(random, depth - 1)});
      break;
    case 4:
      e = node(Op::Or, {random_guard(random, depth - 1), random_guard(random, depth - 1)});
      break;
    default:
      e = node(Op::RegionIs, {});
      e.slot = static_cast<std::uint32_t>(random() % 2);
      break;
  }
  e.type = model::Type::Bool;
  return e;
}

std::vector<model::Region> two_regions() {
  model::LinearConstraint x_at_most_1{{1, 0, 0}, 1, false};
  model::LinearConstraint y_above_x{{1, -1, 0}, 0, true};
  return {{"low", {x_at_most_1}, {}}, {"above", {y_above_x, x_at_most_1}, {}}};
}

bool same(const model::LinearConstraint& a, const model::LinearConstraint& b) {
  return a.coefficients == b.coefficients && a.bound == b.bound && a.strict == b.strict;
}

TEST(GuardReading, AgreesWithTheCompilersReadingOnRandomGuards) {
  std::mt19937 random(20261126);
  const std::vector<model::Region> regions = two_regions();
  int read = 0;
  int refused = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const Expression guard = random_guard(random, 3);
    const auto compiler = model::polyhedral_constraints(guard, kVariables, regions);
    const auto verifier = verify::guard_constraints(guard, kVariables, regions);
    ASSERT_EQ(compiler.has_value(), verifier.has_value()) << "trial " << trial;
    if (!compiler) {
      ++refused;
      continue;
    }
    ++read;
    ASSERT_EQ(compiler->size(), verifier->size()) << "trial " << trial;
    for (std::size_t i = 0; i < compiler->size(); ++i)
      EXPECT_TRUE(same((*compiler)[i], (*verifier)[i])) << "trial " << trial << ", row " << i;
  }
  // Both kinds of guard were drawn often enough for the agreement to mean something.
  EXPECT_GT(read, 400);
  EXPECT_GT(refused, 400);
}

TEST(GuardReading, ReadsAComparisonAsRowsOfAXAtMostB) {
  // 2 x0 - x1 / 2 + 1 >= x2: -2 x0 + x1 / 2 + x2 <= 1.
  const Expression left =
      node(Op::Add, {node(Op::Subtract, {node(Op::Multiply, {constant(2), variable(0)}),
                                         node(Op::Divide, {variable(1), constant(2)})}),
                     constant(1)});
  Expression guard = node(Op::GreaterEqual, {left, variable(2)});
  const auto rows = verify::guard_constraints(guard, kVariables, {});
  ASSERT_TRUE(rows.has_value());
  ASSERT_EQ(rows->size(), 1U);
  EXPECT_EQ((*rows)[0].coefficients, (std::vector<Rational>{-2, Rational(1, 2), 1}));
  EXPECT_EQ((*rows)[0].bound, 1);
  EXPECT_FALSE((*rows)[0].strict);
}

TEST(GuardReading, RefusesProductsOfVariablesAndDivisionByZero) {
  EXPECT_FALSE(verify::guard_constraints(
      node(Op::Less, {node(Op::Multiply, {variable(0), variable(1)}), constant(1)}), kVariables,
      {}));
  EXPECT_FALSE(verify::guard_constraints(
      node(Op::Less, {node(Op::Divide, {variable(0), constant(0)}), constant(1)}), kVariables, {}));
}

}  // namespace
}  // namespace oasis
