#include "prism/constant_overrides.hpp"

#include <algorithm>

#include "support/text.hpp"

namespace oasis::prism {
namespace {

bool is_name(std::string_view text) {
  if (text.empty() || (text[0] >= '0' && text[0] <= '9')) return false;
  return std::all_of(text.begin(), text.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
  });
}

}  // namespace

std::vector<ConstantOverride> read_constant_overrides(std::string_view text,
                                                      DiagnosticEngine& diagnostics) {
  std::vector<ConstantOverride> result;
  while (!trim_blanks(text).empty()) {
    const std::size_t comma = text.find(',');
    const std::string_view entry = trim_blanks(text.substr(0, comma));
    text = comma == std::string_view::npos ? std::string_view() : text.substr(comma + 1);
    const std::size_t equals = entry.find('=');
    const std::string_view name = trim_blanks(entry.substr(0, equals));
    const std::string_view value =
        equals == std::string_view::npos ? "" : trim_blanks(entry.substr(equals + 1));
    if (equals == std::string_view::npos || !is_name(name) || value.empty()) {
      diagnostics.plain_error("--const: expected NAME=VALUE, as in N=4,p=0.1, not " +
                              quoted(entry));
      continue;
    }
    ConstantOverride given{std::string(name), std::string(value), model::Type::Real, 0, {}};
    if (value == "true" || value == "false") {
      given.type = model::Type::Bool;
      given.value = value == "true" ? 1 : 0;
    } else if (const auto number = parse_rational(value)) {
      given.value = *number;
      given.type = number->get_den() == 1 && value.find_first_of(".eE/") == std::string_view::npos
                       ? model::Type::Int
                       : model::Type::Real;
    } else {
      diagnostics.plain_error("--const " + std::string(name) + ": " + quoted(value) +
                              " is not a number, true or false");
      continue;
    }
    const bool repeated = std::any_of(result.begin(), result.end(),
                                      [&](const ConstantOverride& o) { return o.name == name; });
    if (repeated) {
      diagnostics.plain_error("--const gives " + quoted(name) + " twice");
      continue;
    }
    result.push_back(std::move(given));
  }
  return result;
}

}  // namespace oasis::prism
