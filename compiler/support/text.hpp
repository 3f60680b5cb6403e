#pragma once
// Small text helpers shared by diagnostics, readers and emitters.

#include <charconv>
#include <string>
#include <string_view>

#include "text/printable_text.hpp"

namespace oasis {

// 'name', as diagnostics quote names from the input: control bytes escaped, a long name cut
// (common/text/printable_text.hpp).
inline std::string quoted(std::string_view text) {
  return "'" + text::printable_excerpt(text) + "'";
}

// `text` with `"` and `\` escaped, for the inside of a double-quoted string in C++ source or
// a Graphviz label.
inline std::string escape_double_quoted(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out;
}

// `text` without the spaces and tabs at either end: how the line-based readers (.aut labels,
// PRISM's .sta files, --const values) read a field.
inline std::string_view trim_blanks(std::string_view text) {
  const auto blank = [](char c) { return c == ' ' || c == '\t'; };
  while (!text.empty() && blank(text.front()))
    text.remove_prefix(1);
  while (!text.empty() && blank(text.back()))
    text.remove_suffix(1);
  return text;
}

// The shortest decimal that reads back as `value` ("0.1", "1e-06"), as messages and outputs
// print a double.
inline std::string shortest_double(double value) {
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
  return {buffer, end};
}

}  // namespace oasis
