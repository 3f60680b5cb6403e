#include "yaml_schema/codecs.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <system_error>

#include <arpa/inet.h>

namespace oasis::hw::yaml_schema {

namespace {

template <class T>
bool parse_whole(std::string_view text, T& out, int base = 10) {
  if (text.empty()) return false;
  const char* end = text.data() + text.size();
  const auto [rest, error] = std::from_chars(text.data(), end, out, base);
  return error == std::errc() && rest == end;
}

template <class T>
bool parse_finite(std::string_view text, T& out) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  if (text.empty() || text.front() == '+') return false;
  const char* end = text.data() + text.size();
  T value{};
  const auto [rest, error] = std::from_chars(text.data(), end, value);
  if (error != std::errc() || rest != end || !std::isfinite(value)) return false;
  out = value;
  return true;
}

template <class T>
std::string shortest(T value) {
  char buffer[64];
  const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value);
  std::string text(buffer, error == std::errc() ? end : buffer);
  // 1e-12 -> 1.0e-12: YAML 1.1 readers (PyYAML) take a number without a dot for a string.
  const std::size_t exponent = text.find('e');
  if (text.find_first_of(".n") == std::string::npos)
    text.insert(exponent == std::string::npos ? text.size() : exponent, ".0");
  return text;
}

bool plain_safe(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
         c == '.' || c == '/' || c == '-';
}

}  // namespace

bool parse_int64(std::string_view text, std::int64_t& out) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  if (!text.empty() && text.front() == '+') return false;
  return parse_whole(text, out);
}

bool parse_uint64(std::string_view text, std::uint64_t& out) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  if (!text.empty() && text.front() == '+') return false;
  return parse_whole(text, out);
}

bool parse_real(std::string_view text, double& out) {
  return parse_finite(text, out);
}

bool parse_real(std::string_view text, float& out) {
  return parse_finite(text, out);
}

std::string format_real(double value) {
  return shortest(value);
}

std::string format_real(float value) {
  return shortest(value);
}

std::string yaml_string(std::string_view text) {
  bool plain = !text.empty() && ((text.front() >= 'a' && text.front() <= 'z') ||
                                 (text.front() >= 'A' && text.front() <= 'Z') ||
                                 text.front() == '/' || text.front() == '_');
  for (const char c : text)
    plain = plain && plain_safe(c);
  // Words YAML 1.1 readers take for booleans or null.
  for (const std::string_view word : {"true", "false", "yes", "no", "on", "off", "null", "y", "n"})
    if (text.size() == word.size() && std::equal(text.begin(), text.end(), word.begin(),
                                                 [](char a, char b) { return (a | 0x20) == b; }))
      plain = false;
  if (plain) return std::string(text);
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') {
      quoted += '\\';
      quoted += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char escape[8];
      std::snprintf(escape, sizeof escape, "\\x%02x", static_cast<unsigned>(c));
      quoted += escape;
    } else {
      quoted += c;
    }
  }
  return quoted + "\"";
}

std::string describe_bounds(double min, double max, bool min_open, bool max_open) {
  const bool has_min = std::isfinite(min);
  const bool has_max = std::isfinite(max);
  if (has_min && has_max)
    return std::string("in ") + (min_open ? "(" : "[") + format_real(min) + ", " +
           format_real(max) + (max_open ? ")" : "]");
  if (has_min) return (min_open ? "> " : ">= ") + format_real(min);
  if (has_max) return (max_open ? "< " : "<= ") + format_real(max);
  return "(finite)";
}

bool ByteCodec::parse(std::string_view text, std::uint8_t& out) const {
  unsigned value = 0;
  const bool hex = text.size() > 2 && text[0] == '0' && (text[1] == 'x' || text[1] == 'X');
  if (hex ? !parse_whole(text.substr(2), value, 16) : !parse_whole(text, value)) return false;
  if (value > 0xFF) return false;
  out = static_cast<std::uint8_t>(value);
  return true;
}

std::string ByteCodec::format(std::uint8_t value) const {
  char text[8];
  std::snprintf(text, sizeof text, "0x%02x", static_cast<unsigned>(value));
  return text;
}

bool BoolCodec::parse(std::string_view text, bool& out) const {
  if (text == "true" || text == "True" || text == "TRUE") {
    out = true;
    return true;
  }
  if (text == "false" || text == "False" || text == "FALSE") {
    out = false;
    return true;
  }
  return false;
}

bool Ipv4Codec::parse(std::string_view text, std::string& out) const {
  const std::string copy(text);
  in_addr address{};
  if (inet_pton(AF_INET, copy.c_str(), &address) != 1) return false;
  out = copy;
  return true;
}

bool TextCodec::parse(std::string_view text, std::string& out) const {
  if (text.empty()) return false;
  out = std::string(text);
  return true;
}

}  // namespace oasis::hw::yaml_schema
