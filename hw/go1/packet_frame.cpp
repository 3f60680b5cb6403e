#include "go1/packet_frame.hpp"

#include <cstdio>
#include <string>

#include "go1/byte_order.hpp"
#include "go1/crc32.hpp"
#include "go1/protocol.hpp"

namespace oasis::hw::go1 {

namespace {

std::string hex32(std::uint32_t value) {
  char text[16];
  std::snprintf(text, sizeof text, "0x%08x", value);
  return text;
}

}  // namespace

void seal_frame(std::span<std::uint8_t> packet, std::uint8_t level_flag, CrcForm form) {
  packet[0] = kHead0;
  packet[1] = kHead1;
  packet[2] = level_flag;
  const std::size_t length = packet.size();
  put_u32(packet, crc_offset(length), stored_crc(go1_crc32(packet, crc_word_count(length)), form));
}

std::optional<Refused> check_frame(std::span<const std::uint8_t> packet,
                                   std::size_t expected_length,
                                   std::optional<std::uint8_t> expected_level_flag,
                                   AcceptedCrcForms accepted) {
  if (packet.size() != expected_length)
    return Refused{PacketRefusal::kWrongLength, "length " + std::to_string(packet.size()) +
                                                    ", expected " +
                                                    std::to_string(expected_length)};
  if (packet[0] != kHead0 || packet[1] != kHead1)
    return Refused{PacketRefusal::kWrongHead, "head " + std::to_string(packet[0]) + " " +
                                                  std::to_string(packet[1]) + ", expected 254 239"};
  if (expected_level_flag && packet[2] != *expected_level_flag)
    return Refused{PacketRefusal::kWrongLevelFlag, "level flag " + std::to_string(packet[2]) +
                                                       ", expected " +
                                                       std::to_string(*expected_level_flag)};
  if (accepted.size() == 0) return std::nullopt;
  const std::uint32_t stored = get_u32(packet, crc_offset(expected_length));
  const std::uint32_t computed = go1_crc32(packet, crc_word_count(expected_length));
  std::string tried;
  for (const CrcForm form : accepted) {
    if (stored == stored_crc(computed, form)) return std::nullopt;
    tried += (tried.empty() ? "" : ", ") + std::string(crc_form_name(form)) + " " +
             hex32(stored_crc(computed, form));
  }
  return Refused{PacketRefusal::kBadCrc, "crc " + hex32(stored) + " in packet, computed " +
                                             hex32(computed) + "; tried " + tried};
}

}  // namespace oasis::hw::go1
