// Unit tests of the compiled enclosures (compiler/model/enclosure_program.cpp) against the
// tree-walking reference (compiler/model/enclosure.cpp): on thousands of random expressions
// built from every operation the dynamics allow (and some they refuse), over random boxes and
// inputs, both give bit-identical intervals, or the same error (type, message and location).

#include "model/enclosure_program.hpp"

#include <bit>
#include <cstdint>
#include <functional>
#include <iostream>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "model/enclosure.hpp"

namespace oasis::model {
namespace {

// ---- Random expressions; every node has its own source range, so a location is checked ----

class Generator {
 public:
  explicit Generator(std::uint64_t seed) : rng_(seed) {}

  Expression expression(int depth) {
    const int kind = pick(100);
    if (depth == 0 || kind < 15) return leaf();
    if (kind < 18) return refused(depth);
    if (kind < 50) return node(kUnary[pick(std::size(kUnary))], {expression(depth - 1)});
    if (kind < 62) return power(expression(depth - 1));
    return node(kBinary[pick(std::size(kBinary))], {expression(depth - 1), expression(depth - 1)});
  }

  Interval side(bool allow_wide) {
    std::uniform_real_distribution<double> centre(-3, 3);
    static const double kWidths[] = {0, 1e-6, 0.01, 0.2, 1, 3};
    const double c = centre(rng_);
    double w = kWidths[pick(std::size(kWidths))];
    if (allow_wide && pick(50) == 0) w = 1e6;  // exp, powers and tan that overflow
    if (pick(8) == 0) return {0, w};           // sqrt' and log at 0, a kink of abs at an end point
    return {c - w / 2, c + w / 2};
  }

  int pick(std::size_t n) { return static_cast<int>(rng_() % n); }

 private:
  static constexpr Op kUnary[] = {Op::Negate, Op::Abs, Op::Sin, Op::Cos, Op::Tan,
                                  Op::Atan,   Op::Exp, Op::Log, Op::Sqrt};
  static constexpr Op kBinary[] = {Op::Add,    Op::Subtract, Op::Multiply,
                                   Op::Divide, Op::Min,      Op::Max};

  SourceRange next_range() { return {SourceLocation{0, offset_++}, 1}; }

  Expression node(Op op, std::vector<Expression> operands) {
    Expression e;
    e.op = op;
    e.type = Type::Real;
    e.operands = std::move(operands);
    e.range = next_range();
    return e;
  }

  Expression constant(const Rational& value) {
    Rational canonical = value;
    canonical.canonicalize();
    return Expression::make_constant(canonical, Type::Real, next_range());
  }

  Expression variable(Op op, std::uint32_t slot) {
    Expression e = node(op, {});
    e.slot = slot;
    return e;
  }

  // Continuous variables (slots 0..2; 2 is beyond a 2-D box), inputs (slots 0..2; 2 is beyond
  // the two inputs), and constants, a few beyond the doubles or below their precision.
  Expression leaf() {
    const int kind = pick(100);
    if (kind < 45) return variable(Op::ContinuousVariable, pick(100) == 0 ? 2 : pick(2));
    if (kind < 70) return variable(Op::InputVariable, pick(100) == 0 ? 2 : pick(2));
    if (kind == 70) return constant(Rational(mpz_class(1) << 1100, mpz_class(3)));  // > DBL_MAX
    if (kind == 71) return constant(Rational(mpz_class(1), mpz_class(3) << 1100));  // underflows
    std::uniform_int_distribution<int> numerator(-30, 30);
    std::uniform_int_distribution<int> denominator(1, 10);
    return constant(Rational(numerator(rng_), denominator(rng_)));
  }

  // x^n for small n, and now and then an exponent the enclosures refuse.
  Expression power(Expression base) {
    const int kind = pick(40);
    Expression exponent;
    if (kind == 0) {
      exponent = constant(Rational(1, 2));
    } else if (kind == 1) {
      exponent = variable(Op::InputVariable, 0);
    } else if (kind == 2) {
      exponent = constant(Rational(std::numeric_limits<long>::min()));
    } else {
      exponent = constant(Rational(pick(8) - 3));
    }
    return node(Op::Power, {std::move(base), std::move(exponent)});
  }

  // What the dynamics may not contain, or a malformed tree: each a refusal of its own.
  Expression refused(int depth) {
    switch (pick(4)) {
      case 0:
        return node(Op::Floor, {expression(depth - 1)});
      case 1:
        return variable(Op::Variable, 0);
      case 2:
        return node(Op::Add, {expression(depth - 1)});  // an operand missing
      default:
        return node(Op::Less, {expression(depth - 1), expression(depth - 1)});
    }
  }

  std::mt19937_64 rng_;
  std::uint64_t offset_ = 0;
};

// ---- What an evaluation gave: an interval, or an error ----

struct Outcome {
  bool failed = false;
  Interval value;
  std::string kind;  // the exception's type
  std::string message;
  SourceRange where;
};

bool same_double(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

std::string describe(const Outcome& o) {
  if (!o.failed) return to_string(o.value);
  return o.kind + " at " + std::to_string(o.where.begin.offset) + ": " + o.message;
}

// How gtest shows an outcome.
void PrintTo(const Outcome& o, std::ostream* os) {
  *os << describe(o);
}

bool operator==(const Outcome& a, const Outcome& b) {
  if (a.failed != b.failed) return false;
  if (!a.failed) return same_double(a.value.lo, b.value.lo) && same_double(a.value.hi, b.value.hi);
  return a.kind == b.kind && a.message == b.message &&
         a.where.begin.offset == b.where.begin.offset && a.where.length == b.where.length;
}

Outcome failure(const std::string& kind, const std::string& message, SourceRange where) {
  Outcome result;
  result.failed = true;
  result.kind = kind;
  result.message = message;
  result.where = where;
  return result;
}

Outcome outcome(const std::function<Interval()>& evaluate) {
  try {
    Outcome result;
    result.value = evaluate();
    return result;
  } catch (const EnclosureError& error) {
    return failure("EnclosureError", error.what(), error.where);
  } catch (const std::invalid_argument& error) {
    return failure("invalid_argument", error.what(), {});
  } catch (const std::logic_error& error) {
    return failure("logic_error", error.what(), {});
  }
}

struct Counts {
  int cases = 0;
  int natural_failed = 0;
  int mean_value_failed = 0;
  int mean_value_only_failed = 0;
};

// The three enclosures of every component of f over box, tree walk against program.
void compare(std::span<const Expression> f, const std::vector<Interval>& box,
             const std::vector<Interval>& inputs, EnclosureScratch& scratch, Counts& counts,
             int trial) {
  const EnclosureProgram program(f, box.size(), inputs);
  ASSERT_EQ(program.components(), f.size());
  for (std::size_t c = 0; c < f.size(); ++c) {
    ++counts.cases;
    const Outcome tree_natural = outcome([&] { return enclose_natural(f[c], box, inputs); });
    const Outcome compiled_natural = outcome([&] { return program.natural(c, box, scratch); });
    ASSERT_EQ(tree_natural, compiled_natural)
        << "trial " << trial << " natural: " << describe(tree_natural) << " vs "
        << describe(compiled_natural);
    const Outcome tree_mean = outcome([&] { return enclose_mean_value(f[c], box, inputs); });
    const Outcome compiled_mean = outcome([&] { return program.mean_value(c, box, scratch); });
    ASSERT_EQ(tree_mean, compiled_mean)
        << "trial " << trial << " mean value: " << describe(tree_mean) << " vs "
        << describe(compiled_mean);
    counts.natural_failed += tree_natural.failed;
    counts.mean_value_failed += tree_mean.failed;
    counts.mean_value_only_failed += tree_mean.failed && !tree_natural.failed;
  }
  // The whole map: an error of one component is the map's error.
  const Outcome tree_map = outcome([&] {
    const std::vector<Interval> all = enclose_map(f, box, inputs);
    return Interval{all.front().lo, all.back().hi};
  });
  const Outcome compiled_map = outcome([&] {
    std::vector<Interval> all(f.size());
    program.enclose(box, scratch, all);
    return Interval{all.front().lo, all.back().hi};
  });
  ASSERT_EQ(tree_map, compiled_map)
      << "trial " << trial << " map: " << describe(tree_map) << " vs " << describe(compiled_map);
  if (tree_map.failed) return;
  const std::vector<Interval> reference = enclose_map(f, box, inputs);
  std::vector<Interval> compiled(f.size());
  program.enclose(box, scratch, compiled);
  for (std::size_t c = 0; c < f.size(); ++c) {
    ASSERT_TRUE(same_double(reference[c].lo, compiled[c].lo) &&
                same_double(reference[c].hi, compiled[c].hi))
        << "trial " << trial << " map component " << c << ": " << to_string(reference[c]) << " vs "
        << to_string(compiled[c]);
  }
}

TEST(EnclosureProgram, RandomExpressionsGiveTheTreeWalksResultsBitForBit) {
  Generator generate(40);
  EnclosureScratch scratch;  // shared by every program, as a thread of the abstraction does
  Counts counts;
  for (int trial = 0; trial < 12000; ++trial) {
    std::vector<Expression> f;
    const int components = 1 + generate.pick(3);
    for (int c = 0; c < components; ++c)
      f.push_back(generate.expression(1 + (trial + c) % 5));
    // Two variables, and now and then 64 or 65: all a 64-bit mask of partials holds, and more.
    const std::size_t dimension = trial % 20 == 19 ? 65 : trial % 20 == 9 ? 64 : 2;
    std::vector<Interval> box;
    for (std::size_t j = 0; j < dimension; ++j)
      box.push_back(generate.side(true));
    // Inputs are points, as the abstraction's are, or now and then ranges.
    std::vector<Interval> inputs{generate.side(false), generate.side(false)};
    if (generate.pick(4) != 0) {
      for (Interval& u : inputs)
        u = Interval::point(u.lo);
    }
    compare(f, box, inputs, scratch, counts, trial);
    if (HasFatalFailure()) return;
    // A second box through the same program: what binding the inputs kept must not depend
    // on the first.
    std::vector<Interval> other;
    for (std::size_t j = 0; j < dimension; ++j)
      other.push_back(generate.side(false));
    compare(f, other, inputs, scratch, counts, trial);
    if (HasFatalFailure()) return;
  }
  // Every kind of outcome is exercised in numbers.
  std::cout << counts.cases << " components compared; the natural extension failed on "
            << counts.natural_failed << ", the mean-value form on " << counts.mean_value_failed
            << " (" << counts.mean_value_only_failed << " of them with a natural range)\n";
  EXPECT_GT(counts.cases, 40000);
  EXPECT_GT(counts.natural_failed, 10000);
  EXPECT_GT(counts.cases - counts.natural_failed, 25000);
  EXPECT_GT(counts.mean_value_only_failed, 150);
}

// The shipped vehicle's first component, whose input-only sub-expressions are bound once.
TEST(EnclosureProgram, BindsInputOnlySubExpressions) {
  Generator generate(1);
  auto var = [](Op op, std::uint32_t slot) {
    Expression e;
    e.op = op;
    e.type = Type::Real;
    e.slot = slot;
    return e;
  };
  auto apply = [](Op op, std::vector<Expression> operands) {
    Expression e;
    e.op = op;
    e.type = Type::Real;
    e.operands = std::move(operands);
    return e;
  };
  auto constant = [](const Rational& value) {
    return Expression::make_constant(value, Type::Real, {});
  };
  const Expression u0 = var(Op::InputVariable, 0);
  const Expression u1 = var(Op::InputVariable, 1);
  const Expression alpha =
      apply(Op::Atan, {apply(Op::Divide, {apply(Op::Tan, {u1}), constant(Rational(2))})});
  const Expression heading =
      apply(Op::Add, {apply(Op::Add, {alpha, var(Op::ContinuousVariable, 2)}),
                      apply(Op::Multiply, {apply(Op::Multiply, {constant(Rational(3, 20)), u0}),
                                           apply(Op::Tan, {u1})})});
  const Expression rate =
      apply(Op::Divide, {apply(Op::Multiply, {apply(Op::Multiply, {constant(Rational(3, 10)), u0}),
                                              apply(Op::Cos, {heading})}),
                         apply(Op::Cos, {alpha})});
  const std::vector<Expression> f{apply(Op::Add, {var(Op::ContinuousVariable, 0), rate})};
  const std::vector<Interval> inputs{Interval::point(0.6), Interval::point(-0.3)};
  const EnclosureProgram program(f, 3, inputs);
  // x, theta and the six operations over them, and four loads: 0.3 u0, alpha, 0.15 u0 tan(u1)
  // and cos(alpha); the tree has 28 nodes.
  EXPECT_EQ(program.instructions(0), 12U);
  EnclosureScratch scratch;
  Counts counts;
  for (int k = 0; k < 200; ++k) {
    const std::vector<Interval> box{generate.side(false), generate.side(false),
                                    generate.side(false)};
    compare(f, box, inputs, scratch, counts, k);
    if (HasFatalFailure()) return;
  }
  // Once grown, the scratch is reused: an evaluation allocates nothing.
  const Interval* values = scratch.values.data();
  const Interval* gradients = scratch.gradients.data();
  std::vector<Interval> out(1);
  program.enclose(std::vector<Interval>{{1, 1.2}, {2, 2.2}, {0.1, 0.3}}, scratch, out);
  EXPECT_EQ(values, scratch.values.data());
  EXPECT_EQ(gradients, scratch.gradients.data());
}

TEST(EnclosureProgram, RefusesABoxOfTheWrongDimensionOrBadInputs) {
  const std::vector<Expression> f{Expression::make_constant(Rational(1), Type::Real, {})};
  const EnclosureProgram program(f, 2, {});
  EnclosureScratch scratch;
  EXPECT_THROW((void)program.natural(0, std::vector<Interval>{{0, 1}}, scratch),
               std::invalid_argument);
  EXPECT_THROW((void)program.natural(0, std::vector<Interval>{{0, 1}, {1, 0}}, scratch),
               std::invalid_argument);
  const std::vector<Interval> bad_inputs{{1, 0}};
  EXPECT_THROW(EnclosureProgram(f, 2, bad_inputs), std::invalid_argument);
}

}  // namespace
}  // namespace oasis::model
