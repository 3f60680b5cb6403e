#include "go1/crc32.hpp"

#include "go1/byte_order.hpp"

namespace oasis::hw::go1 {

namespace {

constexpr std::uint32_t kPolynomial = 0x04C11DB7u;

std::uint32_t feed_word(std::uint32_t crc, std::uint32_t word) {
  for (int bit = 31; bit >= 0; --bit) {
    const bool input_bit = ((word >> bit) & 1u) != 0;
    const bool top_bit = (crc & 0x80000000u) != 0;
    crc <<= 1;
    if (input_bit != top_bit) crc ^= kPolynomial;
  }
  return crc;
}

}  // namespace

std::uint32_t go1_crc32(std::span<const std::uint8_t> bytes, std::size_t word_count) {
  std::uint32_t crc = 0xFFFFFFFFu;
  for (std::size_t word = 0; word < word_count; ++word)
    crc = feed_word(crc, get_u32(bytes, 4 * word));
  return crc;
}

}  // namespace oasis::hw::go1
