#include "support/rational.hpp"

#include <gtest/gtest.h>

namespace oasis {
namespace {

TEST(ParseDecimal, ExactDecimalsAndExponents) {
  EXPECT_EQ(*parse_decimal("0.125"), Rational(1, 8));
  EXPECT_EQ(*parse_decimal("3"), Rational(3));
  EXPECT_EQ(*parse_decimal("1e-3"), Rational(1, 1000));
  EXPECT_EQ(*parse_decimal("2.5E2"), Rational(250));
  EXPECT_EQ(*parse_decimal("0.1"), Rational(1, 10));  // exact, unlike a double
}

TEST(ParseDecimal, RejectsMalformedText) {
  EXPECT_FALSE(parse_decimal(""));
  EXPECT_FALSE(parse_decimal("."));
  EXPECT_FALSE(parse_decimal("1.2.3"));
  EXPECT_FALSE(parse_decimal("1e"));
  EXPECT_FALSE(parse_decimal("-1"));
  EXPECT_FALSE(parse_decimal("1e999999999"));  // exponent limit, not a huge allocation
}

TEST(ParseRational, FractionsAndSigns) {
  EXPECT_EQ(*parse_rational("1/3"), Rational(1, 3));
  EXPECT_EQ(*parse_rational("-2/4"), Rational(-1, 2));
  EXPECT_EQ(*parse_rational("0.5/2"), Rational(1, 4));
  EXPECT_FALSE(parse_rational("1/0"));
  EXPECT_FALSE(parse_rational("1/"));
}

TEST(Describe, ShowsFractionAndDecimal) {
  EXPECT_EQ(describe(Rational(9, 10)), "9/10 (0.9)");
  EXPECT_EQ(describe(Rational(2)), "2");
}

TEST(ToDouble, RoundsToNearestNotTowardsZero) {
  // GMP's mpq_get_d truncates: 4/5 would come out as 0.7999999999999999.
  EXPECT_EQ(to_double(Rational(4, 5)), 0.8);
  EXPECT_EQ(to_double(Rational(1, 5)), 0.2);
  EXPECT_EQ(to_double(Rational(-4, 5)), -0.8);
  EXPECT_EQ(to_double(Rational(1, 3)), 1.0 / 3.0);
  EXPECT_EQ(to_double(Rational(1, 10)), 0.1);
  EXPECT_EQ(to_double(Rational(7)), 7.0);
  // Every small fraction converts like the correctly rounded division of two doubles.
  for (long q = 1; q < 200; ++q) {
    for (long p = -q; p <= q; ++p) {
      EXPECT_EQ(to_double(Rational(p, q)), static_cast<double>(p) / static_cast<double>(q))
          << p << "/" << q;
    }
  }
}

TEST(RationalPool, InternsEqualValuesOnce) {
  RationalPool pool;
  EXPECT_EQ(pool.intern(Rational(0)), RationalPool::kZero);
  EXPECT_EQ(pool.intern(Rational(1)), RationalPool::kOne);
  const ValueId half = pool.intern(Rational(1, 2));
  EXPECT_EQ(pool.intern(Rational(2, 4)), half);
  EXPECT_EQ(pool[half], Rational(1, 2));
  EXPECT_EQ(pool.size(), 3U);
}

}  // namespace
}  // namespace oasis
