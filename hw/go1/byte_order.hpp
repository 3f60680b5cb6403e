#pragma once
// Little-endian field access at fixed offsets. The Go1 packets are packed little-endian structs
// (FACTS §1 "Packing"), so we read and write each field by offset rather than overlaying a
// struct: that keeps the wire layout explicit and independent of the host's padding rules.

#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>

namespace oasis::hw::go1 {

inline void put_u8(std::span<std::uint8_t> bytes, std::size_t offset, std::uint8_t value) {
  bytes[offset] = value;
}

inline void put_u32(std::span<std::uint8_t> bytes, std::size_t offset, std::uint32_t value) {
  for (std::size_t i = 0; i < 4; ++i)
    bytes[offset + i] = static_cast<std::uint8_t>(value >> (8 * i));
}

inline void put_f32(std::span<std::uint8_t> bytes, std::size_t offset, float value) {
  put_u32(bytes, offset, std::bit_cast<std::uint32_t>(value));
}

inline void put_i16(std::span<std::uint8_t> bytes, std::size_t offset, std::int16_t value) {
  const auto raw = static_cast<std::uint16_t>(value);
  bytes[offset] = static_cast<std::uint8_t>(raw);
  bytes[offset + 1] = static_cast<std::uint8_t>(raw >> 8);
}

inline std::uint32_t get_u32(std::span<const std::uint8_t> bytes, std::size_t offset) {
  std::uint32_t value = 0;
  for (std::size_t i = 0; i < 4; ++i)
    value |= std::uint32_t{bytes[offset + i]} << (8 * i);
  return value;
}

inline float get_f32(std::span<const std::uint8_t> bytes, std::size_t offset) {
  return std::bit_cast<float>(get_u32(bytes, offset));
}

inline std::int16_t get_i16(std::span<const std::uint8_t> bytes, std::size_t offset) {
  const auto raw = static_cast<std::uint16_t>(bytes[offset] | (bytes[offset + 1] << 8));
  return static_cast<std::int16_t>(raw);
}

}  // namespace oasis::hw::go1
