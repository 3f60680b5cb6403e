// UMB state valuations (umb_valuations.hpp): bit fields in and out.

#include "formats/umb_valuations.hpp"

#include <algorithm>
#include <bit>
#include <set>

namespace oasis::formats {
namespace {

std::uint64_t get_bits(std::string_view bytes, std::uint64_t at, std::uint64_t width) {
  std::uint64_t value = 0;
  for (std::uint64_t i = 0; i < width; ++i) {
    const std::uint64_t bit = at + i;
    if (((static_cast<unsigned char>(bytes[bit / 8]) >> (bit % 8)) & 1U) != 0)
      value |= std::uint64_t{1} << i;
  }
  return value;
}

void set_bits(std::string& bytes, std::uint64_t at, std::uint64_t width, std::uint64_t value) {
  for (std::uint64_t i = 0; i < width; ++i) {
    if (((value >> i) & 1U) == 0) continue;
    const std::uint64_t bit = at + i;
    bytes[bit / 8] =
        static_cast<char>(static_cast<unsigned char>(bytes[bit / 8]) | (1U << (bit % 8)));
  }
}

// Bits of the two's-complement form of `value`, sign included.
std::uint64_t signed_width(std::int64_t value) {
  const auto magnitude = static_cast<std::uint64_t>(value < 0 ? -(value + 1) : value);
  return static_cast<std::uint64_t>(std::bit_width(magnitude)) + 1;
}

}  // namespace

bool is_umb_variable_name(std::string_view name) {
  if (name.empty() || (name[0] >= '0' && name[0] <= '9')) return false;
  return std::all_of(name.begin(), name.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
  });
}

bool decode_umb_valuations(const UmbValuationClass& shape, std::string_view bytes, std::uint64_t n,
                           std::vector<std::int64_t>& values, std::string& why) {
  std::size_t variables = 0;
  for (const UmbField& field : shape.fields)
    variables += field.kind == UmbField::Kind::kPadding ? 0 : 1;
  values.assign(n * variables, 0);
  const std::uint64_t stride = shape.bits / 8;
  for (std::uint64_t s = 0; s < n; ++s) {
    const std::string_view state = bytes.substr(s * stride, stride);
    std::uint64_t at = 0;
    std::size_t v = 0;
    for (const UmbField& field : shape.fields) {
      const std::uint64_t raw = get_bits(state, at, field.bits);
      at += field.bits;
      if (field.kind == UmbField::Kind::kPadding) continue;
      __int128 value = 0;
      if (field.kind == UmbField::Kind::kBool) {
        value = raw != 0 ? 1 : 0;
      } else if (field.kind == UmbField::Kind::kInt && field.bits < 64 &&
                 ((raw >> (field.bits - 1)) & 1U) != 0) {
        value = static_cast<__int128>(raw) - (static_cast<__int128>(1) << field.bits);
      } else if (field.kind == UmbField::Kind::kInt) {
        value = static_cast<std::int64_t>(raw);
      } else {
        value = raw;
      }
      value += field.offset;
      if (value < INT64_MIN || value > INT64_MAX) {
        why = "the value of '" + field.name + "' in state " + std::to_string(s) +
              " leaves the 64-bit range";
        return false;
      }
      values[s * variables + v++] = static_cast<std::int64_t>(value);
    }
  }
  return true;
}

std::optional<UmbValuationClass> umb_valuation_class(const model::StateSpace& states) {
  const std::size_t k = states.variables.size();
  if (k == 0 || states.valuations.size() != std::size_t{states.size} * k) return std::nullopt;
  std::set<std::string> seen;
  for (const std::string& name : states.variables) {
    if (!is_umb_variable_name(name) || !seen.insert(name).second) return std::nullopt;
  }
  UmbValuationClass shape;
  for (std::size_t v = 0; v < k; ++v) {
    std::int64_t low = 0;
    std::int64_t high = 0;
    for (std::uint32_t s = 0; s < states.size; ++s) {
      low = std::min(low, states.valuations[s * k + v]);
      high = std::max(high, states.valuations[s * k + v]);
    }
    UmbField field;
    field.name = states.variables[v];
    if (low >= 0) {
      field.kind = UmbField::Kind::kUint;
      field.bits = std::max<std::uint64_t>(1, std::bit_width(static_cast<std::uint64_t>(high)));
    } else {
      field.kind = UmbField::Kind::kInt;
      field.bits = std::max(signed_width(low), signed_width(high));
    }
    shape.bits += field.bits;
    shape.fields.push_back(std::move(field));
  }
  if (shape.bits % 8 != 0) {
    shape.fields.push_back({"", UmbField::Kind::kPadding, 8 - shape.bits % 8, 0});
    shape.bits += shape.fields.back().bits;
  }
  return shape;
}

std::string encode_umb_valuations(const model::StateSpace& states, const UmbValuationClass& shape) {
  const std::uint64_t stride = shape.bits / 8;
  const std::size_t k = states.variables.size();
  std::string bytes(stride * states.size, '\0');
  std::string state;
  for (std::uint32_t s = 0; s < states.size; ++s) {
    state.assign(stride, '\0');
    std::uint64_t at = 0;
    std::size_t v = 0;
    for (const UmbField& field : shape.fields) {
      if (field.kind != UmbField::Kind::kPadding) {
        const auto raw = static_cast<std::uint64_t>(states.valuations[s * k + v++]);
        set_bits(state, at, field.bits,
                 field.bits == 64 ? raw : raw & ((std::uint64_t{1} << field.bits) - 1));
      }
      at += field.bits;
    }
    bytes.replace(s * stride, stride, state);
  }
  return bytes;
}

}  // namespace oasis::formats
