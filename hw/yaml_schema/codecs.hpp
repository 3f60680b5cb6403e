// How each kind of scalar setting is read from, and written to, YAML text. A codec has
//   expected()         what a valid value looks like, for messages ("an integer in 1..65535")
//   parse(text, out)   true and `out` set if `text` is a valid value (range included)
//   format(value)      YAML text that parse() reads back to the same value
// and optionally spellings(), the valid words a misspelt value is compared with. One codec
// instance per key, in a schema; the reader, the writer and the checks all go through it, so
// they cannot disagree. These are the codecs every schema may use; a schema adds its own
// (hw/settings/go1_codecs.hpp).
#pragma once

#include <chrono>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace oasis::hw::yaml_schema {

// Strict number parsing: the whole text, decimal, no spaces. A leading '+' is allowed.
bool parse_int64(std::string_view text, std::int64_t& out);
bool parse_uint64(std::string_view text, std::uint64_t& out);
bool parse_real(std::string_view text, double& out);  // finite only
bool parse_real(std::string_view text, float& out);   // finite only, read as float (exact)

// Shortest text that reads back to the same value, with ".0" added to whole numbers.
std::string format_real(double value);
std::string format_real(float value);

// A YAML scalar for `text`: plain when that is unambiguous, double-quoted otherwise.
std::string yaml_string(std::string_view text);

template <class T>
struct IntegerCodec {
  std::int64_t min = 0;
  std::int64_t max = 0;

  std::string expected() const {
    return "an integer in " + std::to_string(min) + ".." + std::to_string(max);
  }
  bool parse(std::string_view text, T& out) const {
    std::int64_t value = 0;
    if (!parse_int64(text, value) || value < min || value > max) return false;
    out = static_cast<T>(value);
    return true;
  }
  std::string format(T value) const { return std::to_string(value); }
};

struct SeedCodec {
  std::string expected() const { return "an integer in 0..18446744073709551615"; }
  bool parse(std::string_view text, std::uint64_t& out) const { return parse_uint64(text, out); }
  std::string format(std::uint64_t value) const { return std::to_string(value); }
};

// A byte written as hex (0xee) or decimal (238).
struct ByteCodec {
  std::string expected() const { return "a byte: 0x00..0xff or 0..255"; }
  bool parse(std::string_view text, std::uint8_t& out) const;
  std::string format(std::uint8_t value) const;
};

// "any", or a value of the inner codec.
template <class Inner, class T>
struct AnyOrCodec {
  Inner inner;

  std::string expected() const { return "any, or " + inner.expected(); }
  bool parse(std::string_view text, std::optional<T>& out) const {
    if (text == "any") {
      out.reset();
      return true;
    }
    T value{};
    if (!inner.parse(text, value)) return false;
    out = value;
    return true;
  }
  std::string format(const std::optional<T>& value) const {
    return value ? inner.format(*value) : "any";
  }
};

// A finite number within bounds; an infinite bound is no bound.
template <class T>
struct RealCodec {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_open = false;  // true: min itself is excluded
  bool max_open = false;

  std::string expected() const;
  bool parse(std::string_view text, T& out) const {
    T value{};
    if (!parse_real(text, value)) return false;
    const double v = static_cast<double>(value);
    if (min_open ? !(v > min) : !(v >= min)) return false;
    if (max_open ? !(v < max) : !(v <= max)) return false;
    out = value;
    return true;
  }
  std::string format(T value) const { return format_real(value); }
};

// Convenience constructors for the common bounds.
template <class T>
RealCodec<T> positive() {
  return {0.0, std::numeric_limits<double>::infinity(), true, false};
}
template <class T>
RealCodec<T> non_negative() {
  return {0.0, std::numeric_limits<double>::infinity(), false, false};
}
template <class T>
RealCodec<T> closed(double min, double max) {
  return {min, max, false, false};
}

std::string describe_bounds(double min, double max, bool min_open, bool max_open);

template <class T>
std::string RealCodec<T>::expected() const {
  return "a number " + describe_bounds(min, max, min_open, max_open);
}

struct MillisecondsCodec {
  std::int64_t min = 0;
  std::int64_t max = 0;

  std::string expected() const {
    return "a whole number of milliseconds in " + std::to_string(min) + ".." + std::to_string(max);
  }
  bool parse(std::string_view text, std::chrono::milliseconds& out) const {
    std::int64_t value = 0;
    if (!parse_int64(text, value) || value < min || value > max) return false;
    out = std::chrono::milliseconds(value);
    return true;
  }
  std::string format(std::chrono::milliseconds value) const {
    return std::to_string(value.count());
  }
};

struct BoolCodec {
  std::string expected() const { return "true or false"; }
  bool parse(std::string_view text, bool& out) const;
  std::string format(bool value) const { return value ? "true" : "false"; }
};

template <class E>
struct EnumCodec {
  std::vector<std::pair<std::string, E>> names;

  std::string expected() const {
    std::string text = "one of ";
    for (std::size_t i = 0; i < names.size(); ++i)
      text += (i == 0 ? "" : ", ") + names[i].first;
    return text;
  }
  bool parse(std::string_view text, E& out) const {
    for (const auto& [name, value] : names) {
      if (name != text) continue;
      out = value;
      return true;
    }
    return false;
  }
  std::string format(E value) const {
    for (const auto& [name, v] : names)
      if (v == value) return name;
    return "?";
  }
  std::vector<std::string> spellings() const {
    std::vector<std::string> all;
    for (const auto& entry : names)
      all.push_back(entry.first);
    return all;
  }
};

// A dotted-quad IPv4 address; names are not resolved.
struct Ipv4Codec {
  std::string expected() const { return "a dotted-quad IPv4 address such as 192.168.123.161"; }
  bool parse(std::string_view text, std::string& out) const;
  std::string format(const std::string& value) const { return value; }
};

struct TextCodec {
  std::string expected() const { return "a non-empty string"; }
  bool parse(std::string_view text, std::string& out) const;
  std::string format(const std::string& value) const { return yaml_string(value); }
};

// The dotted path of `key` inside the sections `prefix` ("robot", "port" -> "robot.port"), as
// errors and comparisons name keys.
inline std::string dotted_key(const std::vector<std::string>& prefix, std::string_view key) {
  std::string text;
  for (const std::string& part : prefix)
    text += part + ".";
  return text + std::string(key);
}

}  // namespace oasis::hw::yaml_schema
