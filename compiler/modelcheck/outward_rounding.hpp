#pragma once
// Floating-point arithmetic rounded outward, for the sound mode: every lower bound is rounded
// one ulp down and every upper bound one ulp up after each operation. With round-to-nearest the
// computed result is within half an ulp of the exact one, so one ulp outward always contains
// it; this needs no change of the FPU's rounding mode (which compilers do not respect without
// -frounding-math). All quantities here are non-negative, so lower bounds are clamped at 0.

#include <cmath>
#include <limits>

#include "support/rational.hpp"

namespace oasis::modelcheck {

inline double round_down(double x) {
  if (x <= 0) return 0;
  return std::nextafter(x, 0.0);
}
inline double round_up(double x) {
  if (x == std::numeric_limits<double>::infinity()) return x;
  return std::nextafter(x, std::numeric_limits<double>::infinity());
}

inline double add_down(double a, double b) {
  return round_down(a + b);
}
inline double add_up(double a, double b) {
  return round_up(a + b);
}
// A product with a zero factor is exact: no widening then.
inline double multiply_down(double a, double b) {
  return (a == 0 || b == 0) ? 0 : round_down(a * b);
}
inline double multiply_up(double a, double b) {
  return (a == 0 || b == 0) ? 0 : round_up(a * b);
}

// The largest double <= value and the smallest double >= value (value >= 0). GMP's get_d
// truncates, which for a non-negative value is already the one below.
inline double rational_down(const Rational& value) {
  if (sgn(value) <= 0) return 0;
  return value.get_d();
}
inline double rational_up(const Rational& value) {
  const double below = rational_down(value);
  if (sgn(value) <= 0) return 0;
  if (Rational(below) == value) return below;
  return round_up(below);
}

}  // namespace oasis::modelcheck
