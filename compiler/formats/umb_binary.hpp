#pragma once
// The binary arrays of a UMB file (docs/formats.md, "UMB"), as its specification lays them
// out: little-endian throughout; a CSR file is n + 1 uint64 offsets; a TO1 file n values of
// one fixed-size type; a bool array a bitset in whole uint64 words (bit i of the number is
// value i); a rational of S bits (S a positive multiple of 128) is an S/2-bit two's-complement
// numerator followed by an S/2-bit unsigned, non-zero denominator.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "support/rational.hpp"

namespace oasis::formats::umb {

// A value type of the index: "double", "rational", "bool", "uint" and so on, with its size
// in bits (the type's default when the index gives none).
struct ValueType {
  std::string name;
  std::uint64_t bits = 0;
};

[[nodiscard]] inline std::uint64_t load_u64(std::string_view bytes, std::size_t i) {
  std::uint64_t value = 0;
  for (std::size_t b = 0; b < 8; ++b)
    value |= std::uint64_t{static_cast<unsigned char>(bytes[i * 8 + b])} << (8 * b);
  return value;
}
[[nodiscard]] inline std::uint32_t load_u32(std::string_view bytes, std::size_t i) {
  std::uint32_t value = 0;
  for (std::size_t b = 0; b < 4; ++b)
    value |= std::uint32_t{static_cast<unsigned char>(bytes[i * 4 + b])} << (8 * b);
  return value;
}
[[nodiscard]] inline bool load_bit(std::string_view bytes, std::size_t i) {
  return ((static_cast<unsigned char>(bytes[i / 8]) >> (i % 8)) & 1U) != 0;
}
inline void append_u64(std::string& out, std::uint64_t value) {
  for (std::size_t b = 0; b < 8; ++b)
    out.push_back(static_cast<char>((value >> (8 * b)) & 0xffU));
}
inline void append_u32(std::string& out, std::uint32_t value) {
  for (std::size_t b = 0; b < 4; ++b)
    out.push_back(static_cast<char>((value >> (8 * b)) & 0xffU));
}

// The bytes of a bitset of `n` values: whole 64-bit words.
[[nodiscard]] inline std::uint64_t bitset_bytes(std::uint64_t n) {
  return (n + 63) / 64 * 8;
}

// The size in bits of the smallest rational type that holds `value` (a multiple of 128).
[[nodiscard]] std::uint64_t rational_bits(const Rational& value);

// Appends `value` (canonical: its denominator positive) as a rational of `bits` bits, which
// must be at least rational_bits(value).
void append_rational(std::string& out, const Rational& value, std::uint64_t bits);

// The rational of `bits` bits at `bytes` (bits / 8 of them), canonicalised; nullopt when its
// denominator is 0.
[[nodiscard]] std::optional<Rational> load_rational(std::string_view bytes, std::uint64_t bits);

// The IEEE double at `bytes` (8 of them).
[[nodiscard]] double load_double(std::string_view bytes);

// The shortest decimal that reads back as `value` (std::to_chars), e.g. "0.1" for the double
// nearest 1/10; `value` must be finite. A double is read as this decimal, as the text readers
// read the decimals other tools print: docs/formats.md, "UMB".
[[nodiscard]] std::string shortest_decimal(double value);

}  // namespace oasis::formats::umb
