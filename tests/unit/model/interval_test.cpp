// Unit tests of interval arithmetic (compiler/model/interval.cpp) and of the enclosures of
// nonlinear maps built on it (compiler/model/enclosure.cpp): soundness against exact rationals
// (+ - * / sqrt) and long double evaluation (the libm functions, powers and random composed
// expressions) on thousands of random boxes and points; the tightness of the correctly
// rounded operations (one ulp at most, none when exact); sin and cos extrema; each refusal at
// the right sub-expression; the mean-value form on the Van der Pol map; the domain check.

#include "model/interval.hpp"

#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "model/enclosure.hpp"

namespace oasis::model {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = std::numbers::pi;
double next_up(double x) {
  return std::nextafter(x, kInf);
}
double next_down(double x) {
  return std::nextafter(x, -kInf);
}

// ---- Random numbers, intervals and points ----

// Doubles of many magnitudes and signs, with exact small values (0, 1, integers) often.
double random_double(std::mt19937_64& rng, double max_exponent = 6) {
  std::uniform_int_distribution<int> kind(0, 9);
  std::uniform_real_distribution<double> unit(-1, 1);
  switch (kind(rng)) {
    case 0:
      return 0;
    case 1:
      return std::round(unit(rng) * 10);
    case 2:
      return unit(rng) * std::ldexp(1.0, -40);  // small, for the tiny-operand paths
    default: {
      std::uniform_real_distribution<double> exponent(-max_exponent, max_exponent);
      return unit(rng) * std::pow(10.0, exponent(rng));
    }
  }
}

Interval random_interval(std::mt19937_64& rng, double max_exponent = 6) {
  const double a = random_double(rng, max_exponent);
  std::uniform_int_distribution<int> kind(0, 3);
  double b = a;
  if (kind(rng) == 1) b = random_double(rng, max_exponent);
  if (kind(rng) >= 2) {
    std::uniform_real_distribution<double> exponent(-12, 1);
    b = a + std::abs(a + 1) * std::pow(10.0, exponent(rng));
  }
  return {std::min(a, b), std::max(a, b)};
}

// A point of x: either end (where the extremes of the monotone operations are) or inside.
double random_point(const Interval& x, std::mt19937_64& rng) {
  std::uniform_int_distribution<int> kind(0, 3);
  const int k = kind(rng);
  if (k == 0) return x.lo;
  if (k == 1) return x.hi;
  std::uniform_real_distribution<double> unit(0, 1);
  return std::clamp(x.lo + unit(rng) * (x.hi - x.lo), x.lo, x.hi);
}

Rational exact(double x) {
  return Rational(x);
}  // mpq_class(double) is exact

// ---- Exact checks of the correctly rounded operations ----

// The exact range of a * b or a / b over x and y is spanned by the four corners.
void expect_corners_enclosed(const Interval& x, const Interval& y, const Interval& result,
                             const std::function<Rational(const Rational&, const Rational&)>& op,
                             const std::string& what) {
  const double xs[2] = {x.lo, x.hi};
  const double ys[2] = {y.lo, y.hi};
  Rational least = op(exact(x.lo), exact(y.lo));
  Rational most = least;
  for (double a : xs) {
    for (double b : ys) {
      const Rational r = op(exact(a), exact(b));
      least = std::min(least, r);
      most = std::max(most, r);
    }
  }
  ASSERT_LE(exact(result.lo), least) << what << " " << to_string(x) << " " << to_string(y);
  ASSERT_GE(exact(result.hi), most) << what << " " << to_string(x) << " " << to_string(y);
  // Tight: at most one ulp beyond the exact extremes (when no operand is tiny).
  const Interval tiny{-std::ldexp(1.0, -400), std::ldexp(1.0, -400)};
  for (const double v : {x.lo, x.hi, y.lo, y.hi}) {
    if (v != 0 && tiny.contains(v)) return;
  }
  EXPECT_GE(exact(next_up(result.lo)), least) << what << " loose below";
  EXPECT_LE(exact(next_down(result.hi)), most) << what << " loose above";
}

TEST(Interval, ArithmeticEnclosesTheExactCornersAndIsTight) {
  std::mt19937_64 rng(1);
  for (int trial = 0; trial < 20000; ++trial) {
    const Interval x = random_interval(rng);
    const Interval y = random_interval(rng);
    const Interval sum = x + y;
    ASSERT_LE(exact(sum.lo), exact(x.lo) + exact(y.lo));
    ASSERT_GE(exact(sum.hi), exact(x.hi) + exact(y.hi));
    EXPECT_GE(exact(next_up(sum.lo)), exact(x.lo) + exact(y.lo));  // at most one ulp
    EXPECT_LE(exact(next_down(sum.hi)), exact(x.hi) + exact(y.hi));
    const Interval difference = x - y;
    ASSERT_LE(exact(difference.lo), exact(x.lo) - exact(y.hi));
    ASSERT_GE(exact(difference.hi), exact(x.hi) - exact(y.lo));
    expect_corners_enclosed(
        x, y, x * y, [](const Rational& a, const Rational& b) { return Rational(a * b); }, "*");
    if (y.contains(0.0)) {
      EXPECT_THROW((void)(x / y), IntervalError);
    } else {
      expect_corners_enclosed(
          x, y, x / y, [](const Rational& a, const Rational& b) { return Rational(a / b); }, "/");
    }
  }
}

TEST(Interval, ExactResultsAreNotWidened) {
  EXPECT_EQ((Interval{1, 1} - power({1, 1}, 2)).lo, 0.0);
  EXPECT_EQ((Interval{1, 1} - power({1, 1}, 2)).hi, 0.0);
  const Interval product = Interval{0.5, 3} * Interval{-2, 4};
  EXPECT_EQ(product.lo, -6.0);
  EXPECT_EQ(product.hi, 12.0);
  const Interval quotient = Interval{1, 3} / Interval{4, 8};
  EXPECT_EQ(quotient.lo, 0.125);
  EXPECT_EQ(quotient.hi, 0.75);
  EXPECT_EQ(sqrt({0, 4}).lo, 0.0);
  EXPECT_EQ(sqrt({0, 4}).hi, 2.0);
  EXPECT_EQ(power({-2, 3}, 2).lo, 0.0);
  EXPECT_EQ(power({-2, 3}, 2).hi, 9.0);
  EXPECT_EQ(power({-2, -1}, 3).lo, -8.0);
  EXPECT_EQ(power({-2, -1}, 3).hi, -1.0);
  EXPECT_EQ(exp({0, 0}).lo, 1.0);
  EXPECT_EQ(log({1, 1}).hi, 0.0);
  EXPECT_EQ(cos({0, 0}).lo, 1.0);
  EXPECT_EQ(sin({0, 0}).hi, 0.0);
  // 0.1 * 0.1 is not a double: one ulp wide, around the exact product.
  const Interval hundredth = Interval::point(0.1) * Interval::point(0.1);
  EXPECT_EQ(hundredth.hi, next_up(hundredth.lo));
  EXPECT_TRUE(exact(hundredth.lo) < exact(0.1) * exact(0.1));
  EXPECT_TRUE(exact(hundredth.hi) > exact(0.1) * exact(0.1));
}

// interval.cpp steps to a neighbouring double by its bit pattern, not by std::nextafter; the
// widened end points must be nextafter's bit for bit, across signs, zero, subnormals and the
// largest double (the test's next_up and next_down are std::nextafter).
TEST(Interval, WideningStepsAreNextafters) {
  constexpr double kTiny = std::numeric_limits<double>::denorm_min();
  constexpr double kMax = std::numeric_limits<double>::max();
  // A product below 2^-450 in both operands: both sides widened, around 0 and around a
  // subnormal.
  const Interval zero = Interval::point(1e-300) * Interval::point(1e-300);
  EXPECT_EQ(zero.lo, next_down(0.0));
  EXPECT_EQ(zero.hi, next_up(0.0));
  const Interval negative_zero = Interval::point(-1e-300) * Interval::point(1e-300);
  EXPECT_EQ(negative_zero.lo, next_down(-0.0));
  EXPECT_EQ(negative_zero.hi, next_up(-0.0));
  const Interval subnormal = Interval::point(0x1p-520) * Interval::point(-0x1p-520);
  EXPECT_EQ(subnormal.lo, next_down(-0x1p-1040));
  EXPECT_EQ(subnormal.hi, next_up(-0x1p-1040));
  // Sums rounded on one side, both signs; and near the largest double.
  const Interval up = Interval::point(1) + Interval::point(1e-20);
  EXPECT_EQ(up.hi, next_up(1.0));
  const Interval down = Interval::point(-1) + Interval::point(-1e-20);
  EXPECT_EQ(down.lo, next_down(-1.0));
  const Interval high = Interval::point(kMax) + Interval::point(-1e280);
  EXPECT_EQ(high.lo, next_down(kMax));
  EXPECT_EQ(high.hi, kMax);
  // libm results: 4 ulps, then DBL_MIN, which dominates near 0.
  const double e = std::exp(1.0);
  double four_down = e;
  double four_up = e;
  for (int i = 0; i < 4; ++i) {
    four_down = next_down(four_down);
    four_up = next_up(four_up);
  }
  EXPECT_EQ(exp({1, 1}).lo, four_down);
  EXPECT_EQ(exp({1, 1}).hi, four_up);
  EXPECT_EQ(exp({-745, -745}).lo, 0.0);  // exp(-745) is the smallest subnormal, kTiny
  EXPECT_EQ(std::exp(-745.0), kTiny);
}

TEST(Interval, SqrtEnclosesExactlyAndIsTight) {
  std::mt19937_64 rng(2);
  for (int trial = 0; trial < 20000; ++trial) {
    Interval x = random_interval(rng);
    x = {std::abs(x.lo), std::abs(x.hi)};
    if (x.lo > x.hi) std::swap(x.lo, x.hi);
    const Interval root = sqrt(x);
    ASSERT_GE(root.lo, 0.0);
    ASSERT_LE(exact(root.lo) * exact(root.lo), exact(x.lo)) << to_string(x);
    ASSERT_GE(exact(root.hi) * exact(root.hi), exact(x.hi)) << to_string(x);
    if (x.lo > std::ldexp(1.0, -400)) {
      EXPECT_GT(exact(next_up(root.lo)) * exact(next_up(root.lo)), exact(x.lo));
    }
  }
}

TEST(Interval, FromRationalIsTheTightestOutwardInterval) {
  const Rational tenth(1, 10);
  const Interval x = from_rational(tenth);
  EXPECT_TRUE(exact(x.lo) < tenth && tenth < exact(x.hi));
  EXPECT_EQ(x.hi, next_up(x.lo));
  EXPECT_EQ(from_rational(Rational(3, 8)).lo, 0.375);
  EXPECT_EQ(from_rational(Rational(3, 8)).hi, 0.375);
  const Interval third = from_rational(Rational(-1, 3));
  EXPECT_TRUE(exact(third.lo) < Rational(-1, 3) && Rational(-1, 3) < exact(third.hi));
  mpz_class huge;
  mpz_ui_pow_ui(huge.get_mpz_t(), 10, 400);
  try {
    (void)from_rational(Rational(huge));
    ADD_FAILURE() << "10^400 has no finite interval";
  } catch (const IntervalError& error) {
    EXPECT_EQ(error.fault, IntervalFault::kNonFinite);
    EXPECT_NE(std::string(error.what()).find("a non-finite value"), std::string::npos);
  }
  const Interval tiny = from_rational(Rational(mpz_class(1), huge));
  EXPECT_EQ(tiny.lo, 0.0);
  EXPECT_GT(tiny.hi, 0.0);
}

// Checks `function` against `reference` (long double) at random points of random intervals.
void check_against_long_double(const char* name, const std::function<Interval(Interval)>& function,
                               const std::function<long double(long double)>& reference,
                               const std::function<Interval(std::mt19937_64&)>& make) {
  std::mt19937_64 rng(std::hash<std::string>{}(name));
  int checked = 0;
  for (int trial = 0; trial < 5000; ++trial) {
    const Interval x = make(rng);
    Interval result;
    try {
      result = function(x);
    } catch (const IntervalError&) {
      continue;
    }
    ASSERT_TRUE(result.is_finite());
    for (int k = 0; k < 8; ++k) {
      const double point = random_point(x, rng);
      const long double value = reference(point);
      ASSERT_TRUE(result.lo <= value && value <= result.hi)
          << name << "(" << point << ") = " << static_cast<double>(value) << " outside "
          << to_string(result) << " for x in " << to_string(x);
    }
    ++checked;
  }
  EXPECT_GT(checked, 2000) << name;
}

TEST(Interval, LibmFunctionsEncloseLongDoubleValues) {
  auto any = [](std::mt19937_64& rng) { return random_interval(rng, 3); };
  auto positive = [](std::mt19937_64& rng) {
    Interval x = random_interval(rng, 8);
    x = {std::abs(x.lo), std::abs(x.hi)};
    if (x.lo > x.hi) std::swap(x.lo, x.hi);
    return x;
  };
  auto moderate = [](std::mt19937_64& rng) { return random_interval(rng, 2.5); };
  check_against_long_double(
      "exp", [](Interval x) { return exp(x); }, [](long double v) { return expl(v); }, moderate);
  check_against_long_double(
      "log", [](Interval x) { return log(x); }, [](long double v) { return logl(v); }, positive);
  check_against_long_double(
      "sin", [](Interval x) { return sin(x); }, [](long double v) { return sinl(v); }, any);
  check_against_long_double(
      "cos", [](Interval x) { return cos(x); }, [](long double v) { return cosl(v); }, any);
  check_against_long_double(
      "tan", [](Interval x) { return tan(x); }, [](long double v) { return tanl(v); }, any);
  check_against_long_double(
      "atan", [](Interval x) { return atan(x); }, [](long double v) { return atanl(v); }, any);
  check_against_long_double(
      "abs", [](Interval x) { return abs(x); }, [](long double v) { return fabsl(v); }, any);
  check_against_long_double(
      "negate", [](Interval x) { return -x; }, [](long double v) { return -v; }, any);
  for (const int n : {-5, -2, -1, 0, 1, 2, 3, 4, 7, 10}) {
    const std::string name = "power " + std::to_string(n);
    check_against_long_double(
        name.c_str(), [n](Interval x) { return power(x, n); },
        [n](long double v) { return powl(v, static_cast<long double>(n)); },
        [](std::mt19937_64& rng) { return random_interval(rng, 2); });
  }
}

TEST(Interval, MinMaxHullIntersectionWidthMidpoint) {
  const Interval a{-1, 2};
  const Interval b{0.5, 3};
  EXPECT_EQ(min(a, b).lo, -1.0);
  EXPECT_EQ(min(a, b).hi, 2.0);
  EXPECT_EQ(max(a, b).lo, 0.5);
  EXPECT_EQ(max(a, b).hi, 3.0);
  EXPECT_EQ(hull(a, {5, 6}).hi, 6.0);
  EXPECT_EQ(intersection(a, b)->lo, 0.5);
  EXPECT_EQ(intersection(a, b)->hi, 2.0);
  EXPECT_FALSE(intersection(a, {2.5, 3}));
  EXPECT_EQ(a.width(), 3.0);
  EXPECT_EQ(a.midpoint(), 0.5);
  EXPECT_EQ((Interval{-3, 3}).midpoint(), 0.0);
  const Interval wide{-1.7e308, 1.7e308};
  EXPECT_TRUE(wide.contains(wide.midpoint()));
  EXPECT_GE(Interval({0.1, 0.3}).width(), 0.3 - 0.1);
  EXPECT_TRUE(a.contains(0.0));
  EXPECT_FALSE(a.contains(2.5));
  EXPECT_TRUE(b.contains(Interval{1, 2}));
}

// ---- sin and cos: interior extrema ----

TEST(Interval, SinAndCosFindInteriorExtrema) {
  EXPECT_EQ(sin({1.5, 1.6}).hi, 1.0);  // pi/2 inside
  EXPECT_LT(sin({1.6, 3}).hi, 1.0);
  EXPECT_GE(sin({1.6, 3}).hi, std::sin(1.6));
  EXPECT_LE(sin({1.6, 3}).lo, std::sin(3.0));
  EXPECT_GT(sin({1.6, 3}).lo, 0.14);
  EXPECT_EQ(sin({4.6, 4.8}).lo, -1.0);  // 3 pi / 2 inside
  EXPECT_EQ(sin({0, kPi}).hi, 1.0);
  EXPECT_GT(sin({0, kPi}).lo, -1e-15);
  EXPECT_LE(sin({0, kPi}).lo, 0.0);
  EXPECT_EQ(sin({-0.1, 0.1}).hi, next_up(next_up(next_up(next_up(std::sin(0.1))))));
  EXPECT_EQ(cos({-0.5, 0.5}).hi, 1.0);
  EXPECT_EQ(cos({3, 3.3}).lo, -1.0);  // pi inside
  EXPECT_LT(cos({0.1, 3}).hi, 1.0);
  EXPECT_GT(cos({0.1, 3}).lo, -1.0);
  EXPECT_EQ(cos({-7, -6}).hi, 1.0);  // -2 pi inside
  EXPECT_EQ(cos({12, 13}).hi, 1.0);  // 4 pi inside
  // Width 2 pi or more: everything.
  for (const Interval x : {Interval{0, 7}, Interval{100, 106.3}, Interval{-1e6, 1e6}}) {
    EXPECT_EQ(sin(x).lo, -1.0);
    EXPECT_EQ(sin(x).hi, 1.0);
    EXPECT_EQ(cos(x).lo, -1.0);
    EXPECT_EQ(cos(x).hi, 1.0);
  }
  // An end a few ulps from the critical point: undecidable in doubles, so the extremum is in.
  const double half_pi = kPi / 2;
  EXPECT_EQ(sin({1, next_down(half_pi)}).hi, 1.0);
  EXPECT_EQ(sin({half_pi, half_pi}).hi, 1.0);
  EXPECT_EQ(sin({next_up(half_pi), 2}).hi, 1.0);
  EXPECT_EQ(cos({next_up(kPi), 4}).lo, -1.0);
  EXPECT_EQ(cos({1e-300, 1}).hi, 1.0);
}

// Far from 0 the doubles are sparse (an ulp is 1.2e-7 near 6e8): a critical point a fraction
// of an ulp inside the interval must still be found, since sin at the end is then short of
// the extreme by up to 1e-14, far more than the widening covers.
TEST(Interval, SinAndCosFindExtremaAtLargeArguments) {
  const long double pi = std::numbers::pi_v<long double>;
  // The first double past a critical point known in long double (to about 1e-10 here).
  auto double_above = [](long double critical) {
    const long double past = critical + 1e-9L;
    const double d = static_cast<double>(past);
    return d < past ? next_up(d) : d;
  };
  for (long k = 100000000; k < 100002000; ++k) {
    const long double turn = 2 * pi * static_cast<long double>(k);
    const double sin_maximum = double_above(turn + pi / 2);
    const double sin_minimum = double_above(turn + 3 * pi / 2);
    const double cos_maximum = double_above(turn);
    const double cos_minimum = double_above(turn + pi);
    ASSERT_EQ(sin({sin_maximum - 1, sin_maximum}).hi, 1.0) << k;
    ASSERT_EQ(sin({sin_minimum - 1, sin_minimum}).lo, -1.0) << k;
    ASSERT_EQ(cos({cos_maximum - 1, cos_maximum}).hi, 1.0) << k;
    ASSERT_EQ(cos({cos_minimum - 1, cos_minimum}).lo, -1.0) << k;
  }
}

// ---- Expressions ----

SourceRange at(std::uint64_t offset, std::uint32_t length = 1) {
  return {SourceLocation{0, offset}, length};
}

Expression variable(std::uint32_t slot, SourceRange range = {}) {
  Expression e;
  e.op = Op::ContinuousVariable;
  e.type = Type::Real;
  e.slot = slot;
  e.range = range;
  return e;
}

Expression input(std::uint32_t slot) {
  Expression e = variable(slot);
  e.op = Op::InputVariable;
  return e;
}

Expression constant(const Rational& value) {
  Rational canonical = value;
  canonical.canonicalize();
  return Expression::make_constant(canonical, Type::Real, {});
}

Expression apply(Op op, std::vector<Expression> operands, SourceRange range = {}) {
  Expression e;
  e.op = op;
  e.type = Type::Real;
  e.operands = std::move(operands);
  e.range = range;
  return e;
}

Expression power_of(Expression base, std::int64_t n) {
  Expression exponent = Expression::make_constant(Rational(static_cast<long>(n)), Type::Int, {});
  return apply(Op::Power, {std::move(base), std::move(exponent)});
}

Expression operator+(Expression a, Expression b) {
  return apply(Op::Add, {std::move(a), std::move(b)});
}
Expression operator-(Expression a, Expression b) {
  return apply(Op::Subtract, {std::move(a), std::move(b)});
}
Expression operator*(Expression a, Expression b) {
  return apply(Op::Multiply, {std::move(a), std::move(b)});
}
Expression operator/(Expression a, Expression b) {
  return apply(Op::Divide, {std::move(a), std::move(b)});
}

long double to_long_double(const Rational& value) {
  return static_cast<long double>(value.get_num().get_d()) /
         static_cast<long double>(value.get_den().get_d());
}

// f at a point in long double; `scale` grows to the largest magnitude met on the way, the
// measure of the evaluation's own rounding.
long double reference(const Expression& f, std::span<const double> x, std::span<const double> u,
                      long double& scale) {
  auto arg = [&](std::size_t i) { return reference(f.operands[i], x, u, scale); };
  long double value = 0;
  switch (f.op) {
    case Op::Constant:
      value = to_long_double(f.constant);
      break;
    case Op::ContinuousVariable:
      value = x[f.slot];
      break;
    case Op::InputVariable:
      value = u[f.slot];
      break;
    case Op::Add:
      value = arg(0) + arg(1);
      break;
    case Op::Subtract:
      value = arg(0) - arg(1);
      break;
    case Op::Multiply:
      value = arg(0) * arg(1);
      break;
    case Op::Divide:
      value = arg(0) / arg(1);
      break;
    case Op::Negate:
      value = -arg(0);
      break;
    case Op::Power:
      value = powl(arg(0), to_long_double(f.operands[1].constant));
      break;
    case Op::Min:
      value = std::min(arg(0), arg(1));
      break;
    case Op::Max:
      value = std::max(arg(0), arg(1));
      break;
    case Op::Abs:
      value = fabsl(arg(0));
      break;
    case Op::Sin:
      value = sinl(arg(0));
      break;
    case Op::Cos:
      value = cosl(arg(0));
      break;
    case Op::Tan:
      value = tanl(arg(0));
      break;
    case Op::Atan:
      value = atanl(arg(0));
      break;
    case Op::Exp:
      value = expl(arg(0));
      break;
    case Op::Log:
      value = logl(arg(0));
      break;
    case Op::Sqrt:
      value = sqrtl(arg(0));
      break;
    default:
      ADD_FAILURE() << "unexpected op";
  }
  scale = std::max(scale, fabsl(value));
  return value;
}

Expression random_expression(std::mt19937_64& rng, int depth) {
  std::uniform_int_distribution<int> pick(0, 99);
  if (depth == 0 || pick(rng) < 15) {
    const int leaf = pick(rng);
    if (leaf < 30) return variable(0);
    if (leaf < 60) return variable(1);
    if (leaf < 70) return input(0);
    std::uniform_int_distribution<int> numerator(-30, 30);
    std::uniform_int_distribution<int> denominator(1, 10);
    return constant(Rational(numerator(rng), denominator(rng)));
  }
  static const Op kUnary[] = {Op::Negate, Op::Abs, Op::Sin, Op::Cos, Op::Tan,
                              Op::Atan,   Op::Exp, Op::Log, Op::Sqrt};
  static const Op kBinary[] = {Op::Add, Op::Subtract, Op::Multiply, Op::Divide, Op::Min, Op::Max};
  const int kind = pick(rng);
  if (kind < 35) {
    return apply(kUnary[pick(rng) % std::size(kUnary)], {random_expression(rng, depth - 1)});
  }
  if (kind < 45) {
    std::uniform_int_distribution<int> n(-2, 4);
    return power_of(random_expression(rng, depth - 1), n(rng));
  }
  return apply(kBinary[pick(rng) % std::size(kBinary)],
               {random_expression(rng, depth - 1), random_expression(rng, depth - 1)});
}

Interval random_box_side(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> centre(-3, 3);
  static const double kWidths[] = {0, 1e-6, 0.01, 0.2, 1, 3};
  const double c = centre(rng);
  const double w = kWidths[rng() % std::size(kWidths)];
  return {c - w / 2, c + w / 2};
}

bool encloses(const Interval& range, long double value, long double tolerance) {
  return range.lo - tolerance <= value && value <= range.hi + tolerance;
}

TEST(Enclosure, RandomExpressionsEncloseTheirValues) {
  std::mt19937_64 rng(3);
  int evaluated = 0;
  int with_mean_value = 0;
  for (int trial = 0; trial < 6000; ++trial) {
    const Expression f = random_expression(rng, 1 + trial % 4);
    const std::vector<Interval> box{random_box_side(rng), random_box_side(rng)};
    const std::vector<Interval> inputs{random_box_side(rng)};
    Interval natural_range;
    try {
      natural_range = enclose_natural(f, box, inputs);
    } catch (const EnclosureError&) {
      continue;
    }
    ++evaluated;
    std::optional<Interval> mean_value_range;
    try {
      mean_value_range = enclose_mean_value(f, box, inputs);
      ++with_mean_value;
    } catch (const EnclosureError&) {
    }
    const Interval mapped = enclose_map(std::span(&f, 1), box, inputs).at(0);
    ASSERT_TRUE(natural_range.contains(mapped)) << "the intersection is never looser";
    if (mean_value_range) {
      ASSERT_TRUE(mean_value_range->contains(mapped));
    }
    for (int k = 0; k < 10; ++k) {
      const double x[2] = {random_point(box[0], rng), random_point(box[1], rng)};
      const double u[1] = {random_point(inputs[0], rng)};
      long double scale = 1;
      const long double value = reference(f, x, u, scale);
      if (!std::isfinite(value)) continue;
      const long double tolerance = 1e-13L * scale;
      ASSERT_TRUE(encloses(mapped, value, tolerance))
          << "trial " << trial << ": f(" << x[0] << ", " << x[1] << "; " << u[0]
          << ") = " << static_cast<double>(value) << " outside " << to_string(mapped)
          << " (natural " << to_string(natural_range) << ")";
      // The point itself as a box: the tightest case.
      const std::vector<Interval> point_box{Interval::point(x[0]), Interval::point(x[1])};
      const std::vector<Interval> point_input{Interval::point(u[0])};
      try {
        ASSERT_TRUE(encloses(enclose_natural(f, point_box, point_input), value, tolerance))
            << "trial " << trial << " at a point";
      } catch (const EnclosureError&) {
        // a point at a box's edge may still be refused (tan near a pole): sound
      }
    }
  }
  EXPECT_GT(evaluated, 2500);
  EXPECT_GT(with_mean_value, 1500);
}

// ---- Refusals, located ----

// The error `f` raises over box, which must be one, at `where` and with `text`.
void expect_refused(const Expression& f, std::vector<Interval> box, SourceRange where,
                    const std::string& text) {
  try {
    (void)enclose_natural(f, box, {});
    ADD_FAILURE() << "no error; expected: " << text;
  } catch (const EnclosureError& error) {
    EXPECT_EQ(error.where.begin.offset, where.begin.offset) << error.what();
    EXPECT_EQ(error.where.length, where.length) << error.what();
    EXPECT_EQ(std::string(error.what()), text);
  }
}

TEST(Enclosure, RefusalsNameTheSubExpression) {
  const Expression x = variable(0, at(3));
  expect_refused(constant(2) + apply(Op::Divide, {constant(1), x}, at(10, 5)), {{-1, 1}}, at(10, 5),
                 "the divisor can be 0 here: it ranges over [-1, 1]");
  expect_refused(apply(Op::Log, {x}, at(20, 6)), {{0, 1}}, at(20, 6),
                 "log of a range that reaches 0 or below: [0, 1]");
  expect_refused(apply(Op::Sqrt, {x}, at(30, 7)), {{-1, 0}}, at(30, 7),
                 "sqrt of a range below 0: [-1, 0]");
  expect_refused(apply(Op::Tan, {x}, at(40, 6)), {{1.5, 1.7}}, at(40, 6),
                 "tan across a pole: its argument ranges over [1.5, 1.7]");
  expect_refused(constant(1) * apply(Op::Exp, {x}, at(50, 6)), {{0, 1000}}, at(50, 6),
                 "a non-finite value: the result leaves the range of doubles (about +-1.8e308)");
  expect_refused(apply(Op::Floor, {apply(Op::Divide, {constant(1), x})}, at(60, 8)), {{-1, 1}},
                 at(60, 8), "floor is not allowed in dynamics");
  Expression power = power_of(x, -2);
  power.range = at(70, 4);
  expect_refused(power, {{-1, 1}}, at(70, 4),
                 "a negative power of a range that contains 0: [-1, 1]");
  Expression variable_exponent = apply(Op::Power, {x, variable(0, at(80, 1))}, at(78, 4));
  expect_refused(variable_exponent, {{1, 2}}, at(80, 1),
                 "the exponent must be an integer constant here");
  // At the edge of the domain, but not beyond it: allowed.
  EXPECT_EQ(enclose_natural(apply(Op::Sqrt, {x}), std::vector<Interval>{{0, 1}}, {}).lo, 0.0);
  const Expression circle = apply(Op::Sqrt, {constant(1) - power_of(x, 2)});
  const Interval half_circle = enclose_natural(circle, std::vector<Interval>{{-1, 1}}, {});
  EXPECT_EQ(half_circle.lo, 0.0);
  EXPECT_EQ(half_circle.hi, 1.0);
  EXPECT_LT(enclose_natural(apply(Op::Tan, {x}), std::vector<Interval>{{1.5, 1.57}}, {}).hi, 1300);
}

TEST(Enclosure, MeanValueFormFailsOverToTheNaturalExtension) {
  // sqrt' = 1 / (2 sqrt(x)) is unbounded at 0: the mean-value form is refused, the map is not.
  const Expression f = apply(Op::Sqrt, {variable(0)});
  const std::vector<Interval> box{{0, 1}};
  EXPECT_THROW((void)enclose_mean_value(f, box, {}), EnclosureError);
  const std::vector<Interval> mapped = enclose_map(std::span(&f, 1), box, {});
  EXPECT_EQ(mapped.at(0).lo, 0.0);
  EXPECT_EQ(mapped.at(0).hi, 1.0);
}

TEST(Enclosure, AbsMinMaxKinksUseTheHullOfTheirDerivatives) {
  // |x| on [-1, 2], min(x, 1 - x) and max(x, 1 - x) on [0, 1]: sound, and the map is exact
  // where the natural extension is.
  const Expression x = variable(0);
  const std::vector<Expression> f{apply(Op::Abs, {x}), apply(Op::Min, {x, constant(1) - x}),
                                  apply(Op::Max, {x, constant(1) - x})};
  const std::vector<Interval> mapped = enclose_map(f, std::vector<Interval>{{-1, 2}}, {});
  EXPECT_EQ(mapped[0].lo, 0.0);
  EXPECT_EQ(mapped[0].hi, 2.0);
  const std::vector<Interval> unit = enclose_map(f, std::vector<Interval>{{0, 1}}, {});
  EXPECT_TRUE(unit[1].contains(Interval{0, 0.5}));
  EXPECT_TRUE(unit[2].contains(Interval{0.5, 1}));
  // The mean-value form of |x| over [-1, 2]: |0.5| + [-1, 1] * [-1.5, 1.5] = [-1, 2].
  const Interval mean_value = enclose_mean_value(f[0], std::vector<Interval>{{-1, 2}}, {});
  EXPECT_LE(mean_value.lo, -1.0);
  EXPECT_GE(mean_value.hi, 2.0);
}

// x2 + 0.1 * ((1 - x1^2) * x2 - x1): the Van der Pol map's second component, tau = 0.1.
Expression van_der_pol() {
  const Expression x1 = variable(0);
  const Expression x2 = variable(1);
  return x2 + constant(Rational(1, 10)) * ((constant(1) - power_of(x1, 2)) * x2 - x1);
}

TEST(Enclosure, MeanValueFormIsTighterOnASmallVanDerPolBox) {
  const Expression f = van_der_pol();
  const std::vector<Interval> box{{2.0, 2.2}, {-1.0, -0.8}};
  const Interval natural_range = enclose_natural(f, box, {});
  const Interval mean_value_range = enclose_mean_value(f, box, {});
  // Natural: [-0.98, -0.616] (width 0.364); mean value about 0.208 wide.
  EXPECT_LT(mean_value_range.width(), natural_range.width());
  EXPECT_LT(mean_value_range.width(), 0.21);
  EXPECT_GT(natural_range.width(), 0.36);
  const Interval mapped = enclose_map(std::span(&f, 1), box, {}).at(0);
  EXPECT_TRUE(natural_range.contains(mapped));
  EXPECT_TRUE(mean_value_range.contains(mapped));
  // Over many 0.2-wide boxes of the domain: the map is never looser than either form, always
  // sound, and the mean-value form usually wins.
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> corner(-5, 4.8);
  int tighter = 0;
  const int boxes = 2000;
  for (int i = 0; i < boxes; ++i) {
    const double a = corner(rng);
    const double b = corner(rng);
    const std::vector<Interval> small{{a, a + 0.2}, {b, b + 0.2}};
    const Interval n = enclose_natural(f, small, {});
    const Interval m = enclose_mean_value(f, small, {});
    const Interval both = enclose_map(std::span(&f, 1), small, {}).at(0);
    ASSERT_TRUE(n.contains(both) && m.contains(both));
    if (m.width() < n.width()) ++tighter;
    for (int k = 0; k < 10; ++k) {
      const double x[2] = {random_point(small[0], rng), random_point(small[1], rng)};
      long double scale = 1;
      const long double value = reference(f, x, {}, scale);
      ASSERT_TRUE(encloses(both, value, 1e-16L * scale));
    }
  }
  EXPECT_GT(tighter, boxes / 2);
}

TEST(Enclosure, InputsAreReadBySlot) {
  // x + u * sin(x) with u in [0.5, 1]: enclosed for every u, not only the midpoint.
  const Expression f = variable(0) + input(0) * apply(Op::Sin, {variable(0)});
  const std::vector<Interval> box{{1, 1.1}};
  const std::vector<Interval> inputs{{0.5, 1}};
  const Interval mapped = enclose_map(std::span(&f, 1), box, inputs).at(0);
  EXPECT_LE(mapped.lo, 1 + 0.5 * std::sin(1.0));
  EXPECT_GE(mapped.hi, 1.1 + std::sin(1.1));
}

// ---- The domain check ----

TEST(DomainCheck, AcceptsWhatEvaluatesEverywhere) {
  const Expression x = variable(0);
  const std::vector<Interval> domain{{-1, 1}};
  const std::vector<Expression> shifted{constant(1) / (x + constant(2))};
  EXPECT_FALSE(find_domain_error(shifted, domain, {}, 1));
  // cos over [-1.4, 1.4] is [cos 1.4, 1], about [0.17, 1]: no bisection needed either.
  const std::vector<Expression> secant{constant(1) / apply(Op::Cos, {x})};
  EXPECT_FALSE(find_domain_error(secant, std::vector<Interval>{{-1.4, 1.4}}, {}, 1));
  // But a pole of sec inside the domain is refused.
  EXPECT_TRUE(find_domain_error(secant, std::vector<Interval>{{-1.4, 1.6}}, {}, 1000));
}

TEST(DomainCheck, BisectsAwaySpuriousFailures) {
  // x * x over [-1, 1] is [-1, 1] in interval arithmetic, so 1 / (x * x + 1/2) fails over the
  // whole domain; on either half x * x is [0, 1] and it evaluates.
  const Expression x = variable(0);
  const std::vector<Expression> f{constant(1) / (x * x + constant(Rational(1, 2)))};
  const std::vector<Interval> domain{{-1, 1}};
  EXPECT_TRUE(find_domain_error(f, domain, {}, 1));
  EXPECT_TRUE(find_domain_error(f, domain, {}, 2));
  EXPECT_FALSE(find_domain_error(f, domain, {}, 3));
  // In two dimensions: the axis widest relative to the domain is split first (x here, in
  // vain), then y.
  const Expression y = variable(1);
  const std::vector<Expression> g{constant(1) / (y * y + constant(Rational(1, 2))) + x};
  EXPECT_FALSE(find_domain_error(g, std::vector<Interval>{{0, 100}, {-1, 1}}, {}, 10));
}

TEST(DomainCheck, ReportsARealErrorAtItsSmallestBox) {
  const Expression x = variable(0);
  const std::vector<Expression> f{constant(1) + apply(Op::Divide, {constant(1), x}, at(7, 3))};
  const std::vector<Interval> domain{{-1, 1}};
  for (const std::size_t budget : {std::size_t{1}, std::size_t{10}, std::size_t{100000}}) {
    const std::optional<EnclosureError> error = find_domain_error(f, domain, {}, budget);
    ASSERT_TRUE(error) << budget;
    EXPECT_EQ(error->where.begin.offset, 7U);
    EXPECT_EQ(error->where.length, 3U);
    const std::string message = error->what();
    EXPECT_EQ(message.rfind("the divisor can be 0 here: it ranges over ", 0), 0U) << message;
    EXPECT_NE(message.find("where the state ranges over"), std::string::npos) << message;
    if (budget == 100000) {
      // Bisected down to a tiny box next to 0, not the whole domain.
      EXPECT_EQ(message.find("[-1, 1]"), std::string::npos) << message;
    }
  }
}

TEST(DomainCheck, TriesEveryCombinationOfInputs) {
  // 1 / (x + u) over x in [0, 1]: fine for u in {1, 2}, a real error for u = -1/2.
  const Expression f = constant(1) / (variable(0) + input(0) * input(1));
  const std::vector<Interval> domain{{0, 1}};
  const std::vector<std::vector<Interval>> fine{{{1, 1}, {2, 2}}, {{1, 1}}};
  EXPECT_FALSE(find_domain_error(std::span(&f, 1), domain, fine, 100));
  const std::vector<std::vector<Interval>> bad{{{1, 1}, {-0.5, -0.5}}, {{1, 1}}};
  const auto error = find_domain_error(std::span(&f, 1), domain, bad, 100);
  ASSERT_TRUE(error);
  EXPECT_NE(std::string(error->what()).find("with inputs -0.5, 1"), std::string::npos)
      << error->what();
  const std::vector<std::vector<Interval>> none{{}, {{1, 1}}};
  EXPECT_FALSE(find_domain_error(std::span(&f, 1), domain, none, 100));
}

TEST(DomainCheck, ChecksEveryComponent) {
  const Expression x = variable(0);
  const std::vector<Expression> f{x + constant(1), apply(Op::Log, {x}, at(5, 6))};
  const auto error = find_domain_error(f, std::vector<Interval>{{-1, 1}}, {}, 1000);
  ASSERT_TRUE(error);
  EXPECT_EQ(error->where.begin.offset, 5U);
  EXPECT_EQ(std::string(error->what()).rfind("log of a range that reaches 0 or below", 0), 0U);
}

}  // namespace
}  // namespace oasis::model
