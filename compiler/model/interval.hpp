#pragma once
// Closed intervals of doubles with outward rounding, for bounding the continuous dynamics
// x' = f(x, u) over a cell (model/enclosure.hpp; docs/guarantees.md). The contract of every
// operation: for all reals in the operand intervals, the exact real result lies in the result
// interval. Every result is finite: an operation whose enclosure would reach an infinity or a
// NaN throws IntervalError instead (kNonFinite), as do the operations refused on part of their
// operands' range (a divisor containing 0, log of a range reaching 0, ...).
//
// How: each operation computes its end points in the default rounding (to nearest) and widens
// them with std::nextafter, never changing the rounding mode.
//  * + - * / and sqrt are correctly rounded by IEEE-754. Their rounding error is known
//    exactly (an error-free transformation: TwoSum, or the residual an FMA computes), so an
//    end point is widened by one ulp only on the side where the exact value lies, and not at
//    all when the result is exact: 1 - 1 * 1 is [0, 0], so sqrt(1 - x^2) over [-1, 1] is
//    allowed. Where the residual's sign could be lost to underflow (operands below 2^-450)
//    both sides are widened by one ulp.
//  * exp log sin cos tan atan come from the C library, which IEEE-754 does not bind. The one
//    platform assumption (the same kind docs/geometry.md makes for erfc): glibc's libm on
//    x86-64 is within a few ulps of the exact value (its manual's table, libm-test-ulps, lists
//    at most 1 to 2 ulps for these functions in round-to-nearest), and returns C's Annex F
//    special values exactly (exp(0) = 1, log(1) = 0, cos(0) = 1, sin, tan, atan of 0 = 0).
//    Each other result is widened by kLibmUlps = 4 ulps on both sides, and additionally by
//    the smallest normal double (DBL_MIN) in absolute terms, which covers results near zero,
//    where ulps of subnormals are no measure of the error. Results are then clamped to the
//    function's range (sin and cos to [-1, 1], exp to [0, inf), atan to +-pi/2 rounded up).

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>

#include "support/rational.hpp"

namespace oasis::model {

struct Interval {
  double lo = 0;
  double hi = 0;

  static Interval point(double value) { return {value, value}; }

  // hi - lo, rounded up.
  [[nodiscard]] double width() const;
  // A double in [lo, hi] within rounding of (lo + hi) / 2 (the centre of the mean-value form).
  [[nodiscard]] double midpoint() const;
  [[nodiscard]] bool contains(double x) const { return lo <= x && x <= hi; }
  [[nodiscard]] bool contains(const Interval& inner) const {
    return lo <= inner.lo && inner.hi <= hi;
  }
  [[nodiscard]] bool is_finite() const;
};

// Why an operation refused its operands.
enum class IntervalFault : std::uint8_t {
  kDivisorContainsZero,  // x / y with 0 in y; x^-n with 0 in x
  kLogOfNonPositive,     // log(x) with x.lo <= 0
  kSqrtOfNegative,       // sqrt(x) with x.lo < 0 (0 itself is allowed)
  kTanAcrossPole,        // tan(x) where x contains, or may contain, pi/2 + k pi
  kNonFinite,            // a result (or a constant) beyond the finite doubles
};

// The refusal: thrown instead of returning an unsound or infinite interval. `operand` is the
// offending operand (for kNonFinite, the non-finite result); what() is a message fragment in
// the compiler's style ("the divisor can be 0 here: it ranges over [-0.1, 0.3]") that
// model/enclosure.cpp places at the sub-expression.
struct IntervalError : std::domain_error {
  IntervalError(IntervalFault kind, Interval value, const std::string& message)
      : std::domain_error(message), fault(kind), operand(value) {}
  IntervalFault fault;
  Interval operand;
};

// "[-0.1, 0.3]": six significant digits, for messages.
std::string to_string(Interval x);

// The tightest interval of doubles around an exact rational: the nearest double, widened by
// one ulp towards the exact value when it is not exactly that double. kNonFinite beyond the
// largest double.
Interval from_rational(const Rational& value);

Interval operator-(Interval x);
Interval operator+(Interval x, Interval y);
Interval operator-(Interval x, Interval y);
Interval operator*(Interval x, Interval y);
Interval operator/(Interval x, Interval y);  // kDivisorContainsZero when y contains 0

// x^n for any integer n; x^0 = 1, and a negative n is 1 / x^-n (refused when x contains 0).
Interval power(Interval x, std::int64_t n);
Interval sqrt(Interval x);  // kSqrtOfNegative when x.lo < 0
Interval exp(Interval x);
Interval log(Interval x);  // kLogOfNonPositive when x.lo <= 0
Interval sin(Interval x);
Interval cos(Interval x);
Interval tan(Interval x);  // kTanAcrossPole
Interval atan(Interval x);
Interval abs(Interval x);
Interval min(Interval x, Interval y);
Interval max(Interval x, Interval y);

// The smallest interval containing both.
Interval hull(Interval x, Interval y);
// The common part; nullopt when x and y are disjoint.
std::optional<Interval> intersection(Interval x, Interval y);

}  // namespace oasis::model
