#pragma once
// How the robot stores the CRC of a HighState: encrypted (FACTS §1 "CRC"). Unitree's client
// library (unitree_legged_sdk, branch go1, UDP::Recv() in udp.cpp.o) compares the CRC it
// computes over a received high-level packet with decryptCRC(stored), and accepts the stored
// value as it is only when its global `developer` flag is set. So the robot sends
// encryptCRC(crc), and a HighState with the plain CRC is one from a developer-mode peer.
//
//   decrypt(x) = swap(swap(swap(x, 0, 2), 1, 2), 0, 3) ^ 0xEDCAB9DE
//   encrypt(y) = swap(swap(swap(y ^ 0xEDCAB9DE, 1, 2), 0, 3), 0, 2)
//
// where swap(v, i, j) exchanges bytes i and j of v, byte 0 being the least significant (the
// first in memory on the little-endian machines the library runs on). encrypt is decrypt's
// inverse. HighCmd packets carry the plain CRC (the library's SetSend(HighCmd&)).

#include <cstdint>
#include <string_view>

namespace oasis::hw::go1 {

// The forms a stored CRC may take.
enum class CrcForm : std::uint8_t {
  kPlain,      // the CRC itself: HighCmd, and HighState from a developer-mode peer
  kEncrypted,  // encryptCRC(crc): HighState as the robot sends it
};

std::string_view crc_form_name(CrcForm form);

std::uint32_t encrypt_crc(std::uint32_t crc);
std::uint32_t decrypt_crc(std::uint32_t stored);

// What a packet stores for `crc` in the given form.
std::uint32_t stored_crc(std::uint32_t crc, CrcForm form);

}  // namespace oasis::hw::go1
