#include "model/interval.hpp"

#include <algorithm>
#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

namespace oasis::model {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kPi = std::numbers::pi;
// Below this magnitude (and above 0) the residual of a product, quotient or square root could
// underflow to 0 and hide the side of the rounding error: both sides are then widened.
constexpr double kTinyOperand = 0x1p-450;
// The documented platform assumption (interval.hpp): libm's results are within this many ulps.
constexpr int kLibmUlps = 4;
// How close (relative to the number of periods) an end point must come to a critical point of
// sin, cos or tan for the point to count as possibly inside: far more than the rounding of
// (x - offset) / period, so an undecidable case always includes the point.
constexpr double kPeriodSlack = 1e-9;

// std::nextafter(x, +inf), without the call into libm (a fifth of the abstraction's time):
// the neighbouring bit pattern, the sign deciding the direction; 0 goes to the smallest
// subnormal, +inf and NaN stay. Bit for bit what nextafter returns.
double next_up(double x) {
  if (std::isnan(x) || x == kInfinity) return x;
  if (x == 0) return std::numeric_limits<double>::denorm_min();
  const auto bits = std::bit_cast<std::uint64_t>(x);
  return std::bit_cast<double>(x > 0 ? bits + 1 : bits - 1);
}
// std::nextafter(x, -inf), by symmetry.
double next_down(double x) {
  return -next_up(-x);
}

// A result rounded to nearest, and on which side of it the exact result lies: the sign of
// (exact - value), or kEitherSide when that is not known.
struct Nearest {
  double value;
  int side;
};
constexpr int kEitherSide = 2;

double lower(Nearest r) {
  return r.side == 0 || r.side == 1 ? r.value : next_down(r.value);
}
double upper(Nearest r) {
  return r.side == 0 || r.side == -1 ? r.value : next_up(r.value);
}

int sign(double x) {
  return (x > 0) - (x < 0);
}
bool tiny(double x) {
  return x != 0 && std::abs(x) < kTinyOperand;
}

// a + b. TwoSum (Knuth) recovers the rounding error exactly when nothing overflows.
Nearest sum(double a, double b) {
  const double s = a + b;
  if (!std::isfinite(s)) return {s, kEitherSide};
  const double b_part = s - a;
  const double error = (a - (s - b_part)) + (b - b_part);
  return {s, sign(error)};
}

// a * b. The FMA computes a * b - p rounded once; its sign is the error's unless it
// underflows, which operands of at least kTinyOperand rule out.
Nearest product(double a, double b) {
  if (a == 0 || b == 0) return {0.0, 0};
  const double p = a * b;
  if (!std::isfinite(p) || tiny(a) || tiny(b)) return {p, kEitherSide};
  return {p, sign(std::fma(a, b, -p))};
}

// a / b, b != 0. The residual a - q * b has the sign of (a / b - q) * b.
Nearest quotient(double a, double b) {
  if (a == 0) return {0.0, 0};
  const double q = a / b;
  if (!std::isfinite(q) || q == 0 || tiny(q) || tiny(b)) return {q, kEitherSide};
  return {q, sign(std::fma(-q, b, a)) * sign(b)};
}

// sqrt(x), x >= 0. The residual x - s^2 has the sign of sqrt(x) - s.
Nearest square_root(double x) {
  if (x == 0) return {0.0, 0};
  const double s = std::sqrt(x);
  if (tiny(x)) return {s, kEitherSide};
  return {s, sign(std::fma(-s, s, x))};
}

// A libm result widened by kLibmUlps ulps and by DBL_MIN (see interval.hpp); `exact` for the
// special values Annex F fixes.
double libm_lower(double y, bool exact) {
  if (exact) return y;
  double result = y;
  for (int i = 0; i < kLibmUlps; ++i)
    result = next_down(result);
  return std::min(result, y - DBL_MIN);
}
double libm_upper(double y, bool exact) {
  if (exact) return y;
  double result = y;
  for (int i = 0; i < kLibmUlps; ++i)
    result = next_up(result);
  return std::max(result, y + DBL_MIN);
}

std::string format_double(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", x);
  return text;
}

[[noreturn]] void refuse(IntervalFault fault, Interval operand, const std::string& message) {
  throw IntervalError(fault, operand, message);
}

[[noreturn, gnu::cold, gnu::noinline]] void refuse_non_finite(Interval result) {
  refuse(IntervalFault::kNonFinite, result,
         "a non-finite value: the result leaves the range of doubles (about +-1.8e308)");
}

// Every result passes here: an enclosure must be finite. Inlined, the refusal kept out of
// line: called as a function it stalled on reloading the interval it had just spilled.
inline Interval finite(Interval result) {
  if (!(std::isfinite(result.lo) && std::isfinite(result.hi))) refuse_non_finite(result);
  return result;
}

// The enclosure of a product or quotient: the extremes over the four corner results.
template <typename Rounded>
Interval corners(Interval x, Interval y, Rounded rounded) {
  const Nearest r[4] = {rounded(x.lo, y.lo), rounded(x.lo, y.hi), rounded(x.hi, y.lo),
                        rounded(x.hi, y.hi)};
  Interval result{lower(r[0]), upper(r[0])};
  for (const Nearest& n : r) {
    result.lo = std::min(result.lo, lower(n));
    result.hi = std::max(result.hi, upper(n));
  }
  return finite(result);
}

// x * y for x, y >= 0: monotone in both, and never below 0.
Interval multiply_nonnegative(Interval x, Interval y) {
  return finite({std::max(0.0, lower(product(x.lo, y.lo))), upper(product(x.hi, y.hi))});
}

// x^n for x >= 0 and n >= 1, by repeated squaring.
Interval power_nonnegative(Interval x, std::uint64_t n) {
  Interval result{1, 1};
  Interval base = x;
  while (true) {
    if ((n & 1U) != 0) result = multiply_nonnegative(result, base);
    n >>= 1U;
    if (n == 0) return result;
    base = multiply_nonnegative(base, base);
  }
}

// v^n for a point v and odd n >= 1: the sign of v times |v|^n.
Interval odd_power_of_point(double v, std::uint64_t n) {
  const Interval magnitude = power_nonnegative(Interval::point(std::abs(v)), n);
  return v >= 0 ? magnitude : -magnitude;
}

// x^m for m >= 1: odd powers increase; even ones are powers of the magnitudes, whose least is
// 0 when x contains 0.
Interval positive_power(Interval x, std::uint64_t m) {
  if ((m & 1U) != 0) return {odd_power_of_point(x.lo, m).lo, odd_power_of_point(x.hi, m).hi};
  const double far = std::max(std::abs(x.lo), std::abs(x.hi));
  const double near = x.contains(0.0) ? 0 : std::min(std::abs(x.lo), std::abs(x.hi));
  return power_nonnegative({near, far}, m);
}

// Whether offset + k * period lies in [a, b] for some integer k; true when it cannot be told
// apart (an end point within kPeriodSlack periods, relatively, of such a point).
bool may_contain_periodic_point(Interval x, double offset, double period) {
  const double first = (x.lo - offset) / period;
  const double last = (x.hi - offset) / period;
  const double slack = kPeriodSlack * std::max({1.0, std::abs(first), std::abs(last)});
  return std::floor(last + slack) >= std::ceil(first - slack);
}

// sin or cos over x from its values at the end points and its interior extrema: the maxima lie
// at `maximum_at` + 2 k pi, the minima pi further.
template <typename Function>
Interval periodic(Interval x, Function function, double maximum_at) {
  if (x.width() >= 2 * kPi) return {-1, 1};
  const double at_lo = function(x.lo);
  const double at_hi = function(x.hi);
  const bool exact_lo = x.lo == 0 && (at_lo == 0 || at_lo == 1);  // sin(0), cos(0)
  const bool exact_hi = x.hi == 0 && (at_hi == 0 || at_hi == 1);
  Interval result{std::min(libm_lower(at_lo, exact_lo), libm_lower(at_hi, exact_hi)),
                  std::max(libm_upper(at_lo, exact_lo), libm_upper(at_hi, exact_hi))};
  if (may_contain_periodic_point(x, maximum_at, 2 * kPi)) result.hi = 1;
  if (may_contain_periodic_point(x, maximum_at + kPi, 2 * kPi)) result.lo = -1;
  return {std::max(result.lo, -1.0), std::min(result.hi, 1.0)};
}

}  // namespace

double Interval::width() const {
  return upper(sum(hi, -lo));
}

double Interval::midpoint() const {
  if (lo == -hi) return 0;
  const double centre = 0.5 * lo + 0.5 * hi;  // no overflow, unlike (lo + hi) / 2
  return std::clamp(centre, lo, hi);
}

bool Interval::is_finite() const {
  return std::isfinite(lo) && std::isfinite(hi);
}

std::string to_string(Interval x) {
  return "[" + format_double(x.lo) + ", " + format_double(x.hi) + "]";
}

Interval from_rational(const Rational& value) {
  const double nearest = to_double(value);
  if (!std::isfinite(nearest)) {
    refuse(
        IntervalFault::kNonFinite, Interval::point(nearest),
        "a non-finite value: the constant " + describe(value) + " is beyond the range of doubles");
  }
  const int side = sgn(value - Rational(nearest));  // Rational(double) is exact
  return finite({lower({nearest, side}), upper({nearest, side})});
}

Interval operator-(Interval x) {
  return {-x.hi, -x.lo};
}

Interval operator+(Interval x, Interval y) {
  return finite({lower(sum(x.lo, y.lo)), upper(sum(x.hi, y.hi))});
}

Interval operator-(Interval x, Interval y) {
  return x + -y;
}

Interval operator*(Interval x, Interval y) {
  return corners(x, y, [](double a, double b) { return product(a, b); });  // inlined
}

Interval operator/(Interval x, Interval y) {
  if (y.lo <= 0 && 0 <= y.hi) {
    refuse(IntervalFault::kDivisorContainsZero, y,
           "the divisor can be 0 here: it ranges over " + to_string(y));
  }
  return corners(x, y, [](double a, double b) { return quotient(a, b); });
}

Interval power(Interval x, std::int64_t n) {
  if (n == 0) return {1, 1};
  // The magnitude of n without overflow, even for INT64_MIN.
  const std::uint64_t m = n > 0 ? static_cast<std::uint64_t>(n) : 0 - static_cast<std::uint64_t>(n);
  if (n > 0) return positive_power(x, m);
  if (x.contains(0.0)) {
    refuse(IntervalFault::kDivisorContainsZero, x,
           "a negative power of a range that contains 0: " + to_string(x));
  }
  return Interval{1, 1} / positive_power(x, m);
}

Interval sqrt(Interval x) {
  if (x.lo < 0)
    refuse(IntervalFault::kSqrtOfNegative, x, "sqrt of a range below 0: " + to_string(x));
  return finite({std::max(0.0, lower(square_root(x.lo))), upper(square_root(x.hi))});
}

Interval exp(Interval x) {
  return finite({std::max(0.0, libm_lower(std::exp(x.lo), x.lo == 0)),
                 libm_upper(std::exp(x.hi), x.hi == 0)});
}

Interval log(Interval x) {
  if (x.lo <= 0) {
    refuse(IntervalFault::kLogOfNonPositive, x,
           "log of a range that reaches 0 or below: " + to_string(x));
  }
  return finite({libm_lower(std::log(x.lo), x.lo == 1), libm_upper(std::log(x.hi), x.hi == 1)});
}

Interval sin(Interval x) {
  return finite(periodic(
      x, [](double v) { return std::sin(v); }, kPi / 2));
}

Interval cos(Interval x) {
  return finite(periodic(
      x, [](double v) { return std::cos(v); }, 0));
}

Interval tan(Interval x) {
  if (may_contain_periodic_point(x, kPi / 2, kPi)) {
    refuse(IntervalFault::kTanAcrossPole, x,
           "tan across a pole: its argument ranges over " + to_string(x));
  }
  // Between two poles tan increases.
  return finite({libm_lower(std::tan(x.lo), x.lo == 0), libm_upper(std::tan(x.hi), x.hi == 0)});
}

Interval atan(Interval x) {
  const double half_pi_up = next_up(kPi / 2);  // the double pi / 2 is below the real one
  return finite({std::max(-half_pi_up, libm_lower(std::atan(x.lo), x.lo == 0)),
                 std::min(half_pi_up, libm_upper(std::atan(x.hi), x.hi == 0))});
}

Interval abs(Interval x) {
  if (x.lo >= 0) return x;
  if (x.hi <= 0) return -x;
  return {0, std::max(-x.lo, x.hi)};
}

Interval min(Interval x, Interval y) {
  return {std::min(x.lo, y.lo), std::min(x.hi, y.hi)};
}

Interval max(Interval x, Interval y) {
  return {std::max(x.lo, y.lo), std::max(x.hi, y.hi)};
}

Interval hull(Interval x, Interval y) {
  return {std::min(x.lo, y.lo), std::max(x.hi, y.hi)};
}

std::optional<Interval> intersection(Interval x, Interval y) {
  const Interval common{std::max(x.lo, y.lo), std::min(x.hi, y.hi)};
  if (common.lo > common.hi) return std::nullopt;
  return common;
}

}  // namespace oasis::model
