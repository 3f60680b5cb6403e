#pragma once
// The exact sum of the probabilities of one distribution, as readers check it line by line.
// While every term has a 64-bit form (ValueCache::small) the sum is kept as an unreduced
// 64-bit fraction, which for the usual denominators (2, 3, 10^k) never needs a gcd; on the
// first overflow or non-small term it moves to GMP for the rest of the distribution.

#include <cstdint>

#include "formats/value_cache.hpp"

namespace oasis::formats {

class ExactSum {
 public:
  void reset() {
    numerator_ = 0;
    denominator_ = 1;
    exact_ = false;
  }
  void add(ValueId term, const ValueCache& cache) {
    const SmallFraction* small = cache.small(term);
    if (exact_ || small == nullptr || !add_small(*small)) add_exact(cache.pool()[term]);
  }
  // -1, 0 or 1 as the sum is below, equal to or above 1.
  [[nodiscard]] int compare_to_one() const;
  [[nodiscard]] Rational value() const;
  // 1 - sum, interned; the sum must be below 1.
  ValueId interned_remainder(ValueCache& cache) const;

 private:
  bool add_small(const SmallFraction& term);
  void add_exact(const Rational& term);

  std::uint64_t numerator_ = 0;
  std::uint64_t denominator_ = 1;
  bool exact_ = false;  // the sum lives in `big_`
  Rational big_;
};

}  // namespace oasis::formats
