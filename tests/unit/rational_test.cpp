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
