#pragma once
// State valuations of a UMB file (docs/formats.md, "UMB"): each state's variable values,
// bit-packed into one little-endian number per state in the order of the index's variables
// (the first in the least significant bits), padding included, a whole number of bytes per
// state. oasis keeps the form the model IR holds: one valuation class of integer and Boolean
// variables (int, uint, bool; at most 64 bits; an offset added), each value an int64.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "model/explicit_model.hpp"

namespace oasis::formats {

struct UmbField {
  std::string name;  // empty: padding
  enum class Kind { kPadding, kBool, kInt, kUint } kind = Kind::kPadding;
  std::uint64_t bits = 0;
  std::int64_t offset = 0;
};

struct UmbValuationClass {
  std::vector<UmbField> fields;
  std::uint64_t bits = 0;  // of one state, a multiple of 8
};

// Decodes `bytes` (n valuations of `shape`) into one int64 per state and variable; false with
// `why` when a value plus its offset leaves int64.
bool decode_umb_valuations(const UmbValuationClass& shape, std::string_view bytes, std::uint64_t n,
                           std::vector<std::int64_t>& values, std::string& why);

// The class that holds `states`' valuations in the fewest bits (uint where a variable is never
// negative, int otherwise; padding to a whole byte), or nullopt when the states have none or
// their names are not distinct identifiers (which the reader would not take back).
std::optional<UmbValuationClass> umb_valuation_class(const model::StateSpace& states);

// The valuations of `states` in `shape`.
std::string encode_umb_valuations(const model::StateSpace& states, const UmbValuationClass& shape);

// Whether `name` is a PRISM identifier ([A-Za-z_][A-Za-z0-9_]*).
bool is_umb_variable_name(std::string_view name);

}  // namespace oasis::formats
