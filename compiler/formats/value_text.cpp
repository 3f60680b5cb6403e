#include "formats/value_text.hpp"

#include <algorithm>

namespace oasis::formats {

std::optional<std::string> exact_decimal(const Rational& value) {
  // p/q has a finite decimal expansion exactly when q = 2^a 5^b; then p/q = p*2^(n-a)*5^(n-b)
  // / 10^n with n = max(a, b).
  mpz_class rest = value.get_den();
  unsigned long twos = 0;
  unsigned long fives = 0;
  while (mpz_divisible_ui_p(rest.get_mpz_t(), 2) != 0) {
    rest /= 2;
    ++twos;
  }
  while (mpz_divisible_ui_p(rest.get_mpz_t(), 5) != 0) {
    rest /= 5;
    ++fives;
  }
  if (rest != 1) return std::nullopt;
  const unsigned long digits = std::max(twos, fives);
  mpz_class scaled = abs(value.get_num());
  mpz_class factor;
  mpz_ui_pow_ui(factor.get_mpz_t(), 2, digits - twos);
  scaled *= factor;
  mpz_ui_pow_ui(factor.get_mpz_t(), 5, digits - fives);
  scaled *= factor;
  std::string text = scaled.get_str(10);
  if (digits > 0) {
    if (text.size() <= digits) text.insert(0, digits - text.size() + 1, '0');
    text.insert(text.size() - digits, 1, '.');
  }
  if (sgn(value) < 0) text.insert(0, 1, '-');
  return text;
}

std::string ValueText::format(const Rational& value) const {
  if (style_ == ValueStyle::Decimal) {
    if (std::optional<std::string> decimal = exact_decimal(value)) return *decimal;
  }
  return to_string(value);
}

}  // namespace oasis::formats
