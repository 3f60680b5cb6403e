// common/command_line/number_options.hpp: the one rule every number given on a command line of
// oasisc, oasis-sim and oasis-go1 passes (CLI11 validators, checked on the text before CLI11
// converts it).
//
// Why not CLI11's own: PositiveNumber, NonNegativeNumber and Range let "nan" through (every
// comparison with NaN is false), an unsigned option takes "-1" as 2^64 - 1, and a range error
// prints DBL_MAX with 300 digits. Here:
//   real_in(bounds)     a finite decimal number within the bounds; "nan", "inf", "1e999" and
//                       "0x1p3" are refused;
//   whole_in(min, max)  a whole number written in digits only: no sign, no exponent, no point,
//                       so a count or a seed can never wrap around;
//   as_size(option)     a size with an optional unit (8G), no sign, no "nan";
// and every message names the rule in the shortest text that reads back the same bound:
//   --epsilon: 5 is not a number in (0, 1]
// A program exits with status 2 on such an error, as on every usage error.
#pragma once

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <string>
#include <system_error>

#include <CLI/CLI.hpp>

namespace oasis::cli {

// The numbers a real option accepts: [min, max], either end open, infinite ends allowed.
struct RealBounds {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_open = false;
  bool max_open = false;
};

inline RealBounds closed(double min, double max) {
  return {min, max, false, false};
}
inline RealBounds positive(double max = std::numeric_limits<double>::infinity()) {
  return {0.0, max, true, false};
}
inline RealBounds non_negative(double max = std::numeric_limits<double>::infinity()) {
  return {0.0, max, false, false};
}

namespace detail {

// The shortest %g text that reads back to `value` ("0.5", "1e-15", "4e+09").
inline std::string shortest(double value) {
  char text[32];
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(text, sizeof text, "%.*g", digits, value);
    if (std::strtod(text, nullptr) == value) break;
  }
  return text;
}

inline std::string describe(const RealBounds& b) {
  const bool low = std::isfinite(b.min);
  const bool high = std::isfinite(b.max);
  if (low && high)
    return "a number in " + std::string(b.min_open ? "(" : "[") + shortest(b.min) + ", " +
           shortest(b.max) + (b.max_open ? ")" : "]");
  if (low) return std::string("a finite number ") + (b.min_open ? "> " : ">= ") + shortest(b.min);
  if (high) return std::string("a finite number ") + (b.max_open ? "< " : "<= ") + shortest(b.max);
  return "a finite number";
}

// The text as a finite double, or nothing: decimal digits, an optional sign, point and
// exponent; the whole text, no hexadecimal, no "nan" or "inf".
inline bool parse_finite(const std::string& text, double& value) {
  for (const char c : text)
    if (!((c >= '0' && c <= '9') || c == '.' || c == 'e' || c == 'E' || c == '+' || c == '-'))
      return false;
  const char* begin = text.data();
  const char* end = begin + text.size();
  if (begin != end && *begin == '+') ++begin;
  const auto [stop, error] = std::from_chars(begin, end, value);
  return error == std::errc() && stop == end && std::isfinite(value);
}

inline bool within(const RealBounds& b, double v) {
  const bool above = b.min_open ? v > b.min : v >= b.min;
  const bool below = b.max_open ? v < b.max : v <= b.max;
  return above && below;
}

// Shows the text as given, but never more than a line of it.
inline std::string quoted(const std::string& text) {
  constexpr std::size_t kMost = 40;
  std::string shown;
  for (const char c : text.substr(0, kMost))
    shown += (c >= 0x20 && c < 0x7f) ? c : '?';
  return "\"" + shown + (text.size() > kMost ? "...\"" : "\"");
}

}  // namespace detail

// A finite number within `bounds` (see the top of this file).
inline CLI::Validator real_in(RealBounds bounds) {
  const std::string rule = detail::describe(bounds);
  return CLI::Validator(
      [bounds, rule](std::string& text) -> std::string {
        double value = 0.0;
        if (!detail::parse_finite(text, value) || !detail::within(bounds, value))
          return detail::quoted(text) + " is not " + rule;
        return "";
      },
      rule);
}

// A whole number in [min, max], written in digits only (see the top of this file).
inline CLI::Validator whole_in(std::uint64_t min, std::uint64_t max) {
  const std::string rule = "a whole number in " + std::to_string(min) + ".." + std::to_string(max);
  return CLI::Validator(
      [min, max, rule](std::string& text) -> std::string {
        std::uint64_t value = 0;
        const char* begin = text.data();
        const char* end = begin + text.size();
        const auto [stop, error] = std::from_chars(begin, end, value);
        const bool digits =
            !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
        if (!digits || error != std::errc() || stop != end || value < min || value > max)
          return detail::quoted(text) + " is not " + rule;
        return "";
      },
      rule);
}

// A size in bytes, with an optional unit as CLI11's AsSizeValue reads it ("65536", "8G", "64MiB",
// "512 kb"): digits, then letters. CLI11 alone takes "-1" as 2^64 - 1 bytes, which turned a
// size limit off, and "G" as a gigabyte. as_size() attaches this check and the conversion.
inline CLI::Validator size_text() {
  const std::string rule = "a size in bytes, or with a unit (64M, 8G)";
  return CLI::Validator(
      [rule](std::string& text) -> std::string {
        const std::size_t digits = text.find_first_not_of("0123456789");
        std::size_t unit = digits == std::string::npos ? text.size() : digits;
        const bool has_digits = unit > 0;
        while (unit < text.size() && text[unit] == ' ')
          ++unit;
        while (unit < text.size() && ((text[unit] >= 'a' && text[unit] <= 'z') ||
                                      (text[unit] >= 'A' && text[unit] <= 'Z')))
          ++unit;
        if (!has_digits || unit != text.size()) return detail::quoted(text) + " is not " + rule;
        return "";
      },
      rule);
}

// Makes `option` a size in bytes: size_text() on the text as given, then AsSizeValue. CLI11
// runs transforms before checks, the last added first, so both are transforms, in this order.
inline CLI::Option* as_size(CLI::Option* option) {
  return option->transform(CLI::AsSizeValue(false))->transform(size_text());
}

// The largest value of an unsigned option's type, for whole_in(min, max_of<T>()).
template <class T>
constexpr std::uint64_t max_of() {
  return static_cast<std::uint64_t>(std::numeric_limits<T>::max());
}

}  // namespace oasis::cli
