#include "formats/exact_sum.hpp"

#include <numeric>

namespace oasis::formats {
namespace {

Rational from_parts(std::uint64_t numerator, std::uint64_t denominator) {
  Rational value{mpz_class(static_cast<unsigned long>(numerator)),
                 mpz_class(static_cast<unsigned long>(denominator))};
  value.canonicalize();
  return value;
}

}  // namespace

bool ExactSum::add_small(const SmallFraction& term) {
  std::uint64_t numerator = 0;
  std::uint64_t denominator = 0;
  if (term.denominator == denominator_) {
    if (__builtin_add_overflow(numerator_, term.numerator, &numerator)) return false;
    numerator_ = numerator;
    return true;
  }
  // Different denominators: bring both to their lcm, then reduce so that long
  // distributions over mixed denominators stay small.
  const std::uint64_t g = std::gcd(denominator_, term.denominator);
  std::uint64_t left = 0;
  std::uint64_t right = 0;
  if (__builtin_mul_overflow(denominator_ / g, term.denominator, &denominator) ||
      __builtin_mul_overflow(numerator_, term.denominator / g, &left) ||
      __builtin_mul_overflow(term.numerator, denominator_ / g, &right) ||
      __builtin_add_overflow(left, right, &numerator)) {
    return false;
  }
  const std::uint64_t common = std::gcd(numerator, denominator);
  numerator_ = numerator / common;
  denominator_ = denominator / common;
  return true;
}

void ExactSum::add_exact(const Rational& term) {
  if (!exact_) {
    big_ = from_parts(numerator_, denominator_);
    exact_ = true;
  }
  big_ += term;
}

int ExactSum::compare_to_one() const {
  if (exact_) return cmp(big_, 1) < 0 ? -1 : (cmp(big_, 1) > 0 ? 1 : 0);
  return numerator_ < denominator_ ? -1 : (numerator_ > denominator_ ? 1 : 0);
}

Rational ExactSum::value() const {
  return exact_ ? big_ : from_parts(numerator_, denominator_);
}

ValueId ExactSum::interned_remainder(ValueCache& cache) const {
  if (!exact_) return cache.intern_fraction(denominator_ - numerator_, denominator_);
  return cache.intern(Rational(1 - big_));
}

}  // namespace oasis::formats
