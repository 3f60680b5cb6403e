#pragma once
// The Go1 packet checksum (FACTS §1 "CRC"): CRC-32 with polynomial 0x04C11DB7, initial value
// 0xFFFFFFFF, no reflection and no final XOR, fed one 32-bit word at a time, each word read
// little-endian from the packet and shifted in most significant bit first.

#include <cstddef>
#include <cstdint>
#include <span>

namespace oasis::hw::go1 {

// The checksum of the first `word_count` little-endian words of `bytes`
// (bytes.size() >= 4 * word_count).
std::uint32_t go1_crc32(std::span<const std::uint8_t> bytes, std::size_t word_count);

}  // namespace oasis::hw::go1
