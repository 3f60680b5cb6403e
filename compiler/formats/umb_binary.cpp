// UMB's numbers in bytes (umb_binary.hpp), on GMP's import and export of limbs.

#include "formats/umb_binary.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cstring>

namespace oasis::formats::umb {
namespace {

// Bits of the two's-complement form of `value`, sign bit included.
std::uint64_t signed_bits(const mpz_class& value) {
  if (sgn(value) >= 0) return mpz_sizeinbase(value.get_mpz_t(), 2) + (sgn(value) > 0 ? 1 : 0);
  const mpz_class magnitude = -value - 1;  // -2^k needs k + 1 bits
  return (sgn(magnitude) == 0 ? 0 : mpz_sizeinbase(magnitude.get_mpz_t(), 2)) + 1;
}

// Appends the low `bytes` bytes of the non-negative `value`, least significant first.
void append_magnitude(std::string& out, const mpz_class& value, std::size_t bytes) {
  const std::size_t start = out.size();
  out.resize(start + bytes, '\0');
  if (sgn(value) == 0) return;
  std::size_t count = 0;
  mpz_export(out.data() + start, &count, -1, 1, 0, 0, value.get_mpz_t());
}

mpz_class load_unsigned(std::string_view bytes) {
  mpz_class value;
  mpz_import(value.get_mpz_t(), bytes.size(), -1, 1, 0, 0, bytes.data());
  return value;
}

}  // namespace

std::uint64_t rational_bits(const Rational& value) {
  const std::uint64_t half = std::max(
      {signed_bits(value.get_num()),
       static_cast<std::uint64_t>(mpz_sizeinbase(value.get_den_mpz_t(), 2)), std::uint64_t{1}});
  return (half + 63) / 64 * 128;
}

void append_rational(std::string& out, const Rational& value, std::uint64_t bits) {
  const std::size_t half = bits / 16;  // bytes of each part
  mpz_class numerator = value.get_num();
  if (sgn(numerator) < 0) {
    mpz_class power;
    mpz_ui_pow_ui(power.get_mpz_t(), 2, bits / 2);
    numerator += power;  // two's complement
  }
  append_magnitude(out, numerator, half);
  append_magnitude(out, value.get_den(), half);
}

std::optional<Rational> load_rational(std::string_view bytes, std::uint64_t bits) {
  const std::size_t half = bits / 16;
  mpz_class numerator = load_unsigned(bytes.substr(0, half));
  if ((static_cast<unsigned char>(bytes[half - 1]) & 0x80U) != 0) {
    mpz_class power;
    mpz_ui_pow_ui(power.get_mpz_t(), 2, bits / 2);
    numerator -= power;
  }
  mpz_class denominator = load_unsigned(bytes.substr(half, half));
  if (sgn(denominator) == 0) return std::nullopt;
  Rational value(numerator, denominator);
  value.canonicalize();
  return value;
}

double load_double(std::string_view bytes) {
  const std::uint64_t raw = load_u64(bytes, 0);
  return std::bit_cast<double>(raw);
}

std::string shortest_decimal(double value) {
  std::array<char, 64> text{};
  const auto result = std::to_chars(text.data(), text.data() + text.size(), value);
  return {text.data(), result.ptr};
}

}  // namespace oasis::formats::umb
