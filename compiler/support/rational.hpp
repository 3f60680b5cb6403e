#pragma once
// Exact rationals (GMP) for every probability and reward the compiler handles, and the
// parsing and printing of the notations specs and model files use: integers, decimals with
// an optional exponent (`0.125`, `1e-3`) and fractions (`1/3`).

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include <gmpxx.h>

namespace oasis {

using Rational = mpq_class;

// Parses `digits[.digits][e[+-]digits]` exactly; no sign. Returns nullopt on bad syntax.
std::optional<Rational> parse_decimal(std::string_view text);
// Parses a decimal or `p/q` where p and q are decimals, with an optional leading sign.
std::optional<Rational> parse_rational(std::string_view text);

// "1/3", "2", "-5/2": exact and canonical.
std::string to_string(const Rational& value);
// "1/3 (0.333333)" for messages; plain "2" when the value is an integer. A value whose exact
// text is longer than kMaxDescribedDigits is shown as "about 1e+1000 (an exact fraction of N
// characters)", so that a hostile number cannot make a message megabytes long.
std::string describe(const Rational& value);
inline constexpr std::size_t kMaxDescribedDigits = 48;
// "1.23457e+1000": six significant digits, for any magnitude (not limited to doubles).
std::string scientific(const Rational& value);
// The nearest double (what emitted tables carry).
double to_double(const Rational& value);
// The bits of the longer of the (canonical) numerator and denominator: the measure the
// number-size limit (limits::kDefaultMaxNumberBits, --max-number-bits) bounds. Products and
// sums of numbers of at most n bits have at most 2n + 1, so checking every result keeps all
// exact arithmetic within a constant factor of the limit.
std::size_t bit_size(const Rational& value);
// "about 1e-399996 is too long to compute with exactly: its numerator or denominator has N
// bits, more than the limit of M (--max-number-bits)", for a value over the limit. The value is
// shown in scientific form only: its exact text would take long to print and be unreadable.
std::string too_long_message(const Rational& value, std::size_t max_bits);
// The same text about another subject ("number of 9000 characters"), of `bits` bits.
std::string too_long_message(std::string_view subject, std::size_t bits, std::size_t max_bits);

std::size_t hash_value(const Rational& value);

struct RationalHash {
  std::size_t operator()(const Rational& value) const { return hash_value(value); }
};

using ValueId = std::uint32_t;

// The distinct rationals of a model. Edges and rewards refer to them by a 4-byte id, so a
// model with 10^7 edges and a handful of distinct probabilities stays small and exact.
class RationalPool {
 public:
  RationalPool();  // id 0 is always 0 and id 1 is always 1

  ValueId intern(const Rational& value);
  [[nodiscard]] const Rational& operator[](ValueId id) const { return values_[id]; }
  [[nodiscard]] std::size_t size() const { return values_.size(); }

  static constexpr ValueId kZero = 0;
  static constexpr ValueId kOne = 1;

 private:
  std::vector<Rational> values_;
  std::unordered_map<Rational, ValueId, RationalHash> index_;
};

}  // namespace oasis
