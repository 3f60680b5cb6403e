#pragma once
// The frame shared by HighCmd and HighState: head FE EF at byte 0, the level flag at byte 2 and a
// CRC over the first (length / 4 - 1) words stored in the last four bytes (FACTS §1 "CRC": the
// SDK covers bytes 0..123 of a HighCmd and 0..1079 of a HighState; the bytes between the covered
// words and the CRC are not checked). The CRC is stored plain or encrypted (crc_cipher.hpp).

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <span>

#include "go1/crc_cipher.hpp"
#include "go1/packet_refusal.hpp"

namespace oasis::hw::go1 {

// How many words the CRC covers in a packet of `length` bytes, and where it is stored.
constexpr std::size_t crc_word_count(std::size_t length) {
  return length / 4 - 1;
}
constexpr std::size_t crc_offset(std::size_t length) {
  return length - 4;
}

// Writes head, level flag and the CRC in `form` into `packet` (its other bytes already filled
// in).
void seal_frame(std::span<std::uint8_t> packet, std::uint8_t level_flag, CrcForm form);

// The CRC forms a receiver accepts, in the order they are tried; none: the CRC is not checked.
using AcceptedCrcForms = std::initializer_list<CrcForm>;

// Checks length, head, level flag (when one is expected) and CRC (stored in one of the
// `accepted` forms), in that order; nullopt if all hold. A CRC refusal names the stored value,
// the computed one and every form tried.
std::optional<Refused> check_frame(std::span<const std::uint8_t> packet,
                                   std::size_t expected_length,
                                   std::optional<std::uint8_t> expected_level_flag,
                                   AcceptedCrcForms accepted);

}  // namespace oasis::hw::go1
