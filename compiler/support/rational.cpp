#include "support/rational.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <utility>

#include "support/limits.hpp"

namespace oasis {
namespace {

bool is_digit(char c) {
  return c >= '0' && c <= '9';
}

// Exponents beyond this are refused (support/limits.hpp).
constexpr long kMaxExponent = limits::kMaxDecimalExponent;

Rational power_of_ten(long exponent) {
  mpz_class power;
  mpz_ui_pow_ui(power.get_mpz_t(), 10, static_cast<unsigned long>(exponent));
  return Rational(power);
}

}  // namespace

std::optional<Rational> parse_decimal(std::string_view text) {
  std::size_t i = 0;
  std::string digits;
  long scale = 0;  // number of digits after the point
  while (i < text.size() && is_digit(text[i]))
    digits += text[i++];
  if (i < text.size() && text[i] == '.') {
    ++i;
    while (i < text.size() && is_digit(text[i])) {
      digits += text[i++];
      ++scale;
    }
  }
  if (digits.empty()) return std::nullopt;
  long exponent = 0;
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    bool negative = false;
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) negative = text[i++] == '-';
    const char* first = text.data() + i;
    const char* last = text.data() + text.size();
    auto [end, ec] = std::from_chars(first, last, exponent);
    if (ec != std::errc() || end == first || exponent > kMaxExponent) return std::nullopt;
    i += static_cast<std::size_t>(end - first);
    if (negative) exponent = -exponent;
  }
  if (i != text.size()) return std::nullopt;
  Rational value(mpz_class(digits, 10));
  const long shift = exponent - scale;
  if (shift > 0) value *= power_of_ten(shift);
  if (shift < 0) value /= power_of_ten(-shift);
  value.canonicalize();
  return value;
}

std::optional<Rational> parse_rational(std::string_view text) {
  bool negative = false;
  if (!text.empty() && (text[0] == '-' || text[0] == '+')) {
    negative = text[0] == '-';
    text.remove_prefix(1);
  }
  const std::size_t slash = text.find('/');
  std::optional<Rational> value;
  if (slash == std::string_view::npos) {
    value = parse_decimal(text);
  } else {
    auto numerator = parse_decimal(text.substr(0, slash));
    auto denominator = parse_decimal(text.substr(slash + 1));
    if (!numerator || !denominator || *denominator == 0) return std::nullopt;
    value = *numerator / *denominator;
  }
  if (value && negative) *value = -*value;
  return value;
}

std::string to_string(const Rational& value) {
  return value.get_str(10);
}

// mpq_get_d truncates towards zero, so 4/5 would become 0.7999999999999999. The nearest
// double is either that one or its neighbour away from zero; exact comparison decides.
double to_double(const Rational& value) {
  const double truncated = value.get_d();
  if (!std::isfinite(truncated)) return truncated;
  const double away = std::nextafter(truncated, value > 0 ? HUGE_VAL : -HUGE_VAL);
  if (!std::isfinite(away)) return truncated;
  const Rational below_error = abs(value - Rational(truncated));
  const Rational above_error = abs(Rational(away) - value);
  if (above_error < below_error) return away;
  if (below_error < above_error) return truncated;
  // A tie: round half to even, like IEEE-754 (the even one has a zero last mantissa bit).
  std::uint64_t bits = 0;
  std::memcpy(&bits, &truncated, sizeof bits);
  return (bits & 1U) == 0 ? truncated : away;
}

std::size_t bit_size(const Rational& value) {
  return std::max(mpz_sizeinbase(value.get_num_mpz_t(), 2),
                  mpz_sizeinbase(value.get_den_mpz_t(), 2));
}

std::string too_long_message(std::string_view subject, std::size_t bits, std::size_t max_bits) {
  return std::string(subject) +
         " is too long to compute with exactly: its numerator or denominator has " +
         std::to_string(bits) + " bits, more than the limit of " + std::to_string(max_bits) +
         " (--max-number-bits)";
}

std::string too_long_message(const Rational& value, std::size_t max_bits) {
  return too_long_message("about " + scientific(value), bit_size(value), max_bits);
}

std::string scientific(const Rational& value) {
  // mpf's exponent is a long, so this works far beyond the range of a double.
  const mpf_class approximate(value, 64);
  mp_exp_t exponent = 0;
  char* digits = mpf_get_str(nullptr, &exponent, 10, 6, approximate.get_mpf_t());
  std::string mantissa = digits;
  void (*release)(void*, std::size_t) = nullptr;
  mp_get_memory_functions(nullptr, nullptr, &release);
  release(digits, std::strlen(digits) + 1);
  if (mantissa.empty() || mantissa == "0") return "0";
  const bool negative = mantissa[0] == '-';
  if (negative) mantissa.erase(0, 1);
  std::string text = negative ? "-" : "";
  text += mantissa.substr(0, 1);
  if (mantissa.size() > 1) text += "." + mantissa.substr(1);
  return text + "e" + (exponent - 1 >= 0 ? "+" : "") + std::to_string(exponent - 1);
}

std::string describe(const Rational& value) {
  std::string exact = to_string(value);
  if (exact.size() > kMaxDescribedDigits) {
    return "about " + scientific(value) + " (an exact fraction of " + std::to_string(exact.size()) +
           " characters)";
  }
  if (value.get_den() == 1) return exact;
  char decimal[32];
  std::snprintf(decimal, sizeof decimal, "%.6g", to_double(value));
  return exact + " (" + decimal + ")";
}

std::size_t hash_value(const Rational& value) {
  // Assumes canonical form (see RationalPool::intern).
  // Hash the limbs of numerator and denominator; equal canonical rationals hash equally.
  auto hash_integer = [](mpz_srcptr z, std::size_t seed) {
    const std::size_t limbs = mpz_size(z);
    seed ^= static_cast<std::size_t>(mpz_sgn(z)) + 0x9e3779b97f4a7c15ULL;
    for (std::size_t i = 0; i < limbs; ++i) {
      seed = (seed ^ static_cast<std::size_t>(mpz_getlimbn(z, static_cast<mp_size_t>(i)))) *
             0x100000001b3ULL;
    }
    return seed;
  };
  return hash_integer(value.get_den_mpz_t(),
                      hash_integer(value.get_num_mpz_t(), 0xcbf29ce484222325ULL));
}

RationalPool::RationalPool() {
  intern(Rational(0));
  intern(Rational(1));
}

ValueId RationalPool::intern(const Rational& value) {
  // mpq_class(2, 4) is not reduced by GMP; hashing and equality need the canonical form.
  Rational canonical = value;
  canonical.canonicalize();
  auto [it, inserted] = index_.try_emplace(canonical, static_cast<ValueId>(values_.size()));
  if (inserted) values_.push_back(std::move(canonical));
  return it->second;
}

}  // namespace oasis
