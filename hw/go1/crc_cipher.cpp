#include "go1/crc_cipher.hpp"

namespace oasis::hw::go1 {

namespace {

constexpr std::uint32_t kCrcKey = 0xEDCAB9DEu;

// Exchanges bytes i and j of `value` (byte 0: the least significant).
constexpr std::uint32_t swap_bytes(std::uint32_t value, unsigned i, unsigned j) {
  const std::uint32_t byte_i = (value >> (8 * i)) & 0xFFu;
  const std::uint32_t byte_j = (value >> (8 * j)) & 0xFFu;
  value &= ~((0xFFu << (8 * i)) | (0xFFu << (8 * j)));
  return value | (byte_i << (8 * j)) | (byte_j << (8 * i));
}

}  // namespace

std::string_view crc_form_name(CrcForm form) {
  return form == CrcForm::kEncrypted ? "encrypted" : "plain";
}

std::uint32_t encrypt_crc(std::uint32_t crc) {
  return swap_bytes(swap_bytes(swap_bytes(crc ^ kCrcKey, 1, 2), 0, 3), 0, 2);
}

std::uint32_t decrypt_crc(std::uint32_t stored) {
  return swap_bytes(swap_bytes(swap_bytes(stored, 0, 2), 1, 2), 0, 3) ^ kCrcKey;
}

std::uint32_t stored_crc(std::uint32_t crc, CrcForm form) {
  return form == CrcForm::kEncrypted ? encrypt_crc(crc) : crc;
}

}  // namespace oasis::hw::go1
