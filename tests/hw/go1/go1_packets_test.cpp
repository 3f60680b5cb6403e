// The Go1 packets: the CRC against an independent CRC-32/MPEG-2, golden HighCmd bytes written
// field by field at the offsets of FACTS §1, round trips, and every refusal.

#include <bit>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "go1/crc32.hpp"
#include "go1/crc_cipher.hpp"
#include "go1/high_cmd.hpp"
#include "go1/high_state.hpp"

namespace oasis::hw::go1 {
namespace {

// CRC-32/MPEG-2 over bytes, bit by bit: the textbook definition, written independently of
// go1_crc32 (which works on little-endian words).
std::uint32_t crc32_mpeg2(const std::vector<std::uint8_t>& bytes) {
  std::uint32_t crc = 0xFFFFFFFFu;
  for (std::uint8_t byte : bytes) {
    crc ^= std::uint32_t{byte} << 24;
    for (int bit = 0; bit < 8; ++bit)
      crc = (crc & 0x80000000u) ? (crc << 1) ^ 0x04C11DB7u : crc << 1;
  }
  return crc;
}

// FACTS §1: the Go1 CRC equals MPEG-2 over the bytes with each 4-byte group reversed.
std::uint32_t crc_by_mpeg2(const std::vector<std::uint8_t>& bytes, std::size_t words) {
  std::vector<std::uint8_t> reversed;
  for (std::size_t w = 0; w < words; ++w)
    for (int i = 3; i >= 0; --i)
      reversed.push_back(bytes[4 * w + static_cast<std::size_t>(i)]);
  return crc32_mpeg2(reversed);
}

void write_le32(std::vector<std::uint8_t>& bytes, std::size_t offset, std::uint32_t value) {
  bytes[offset] = static_cast<std::uint8_t>(value);
  bytes[offset + 1] = static_cast<std::uint8_t>(value >> 8);
  bytes[offset + 2] = static_cast<std::uint8_t>(value >> 16);
  bytes[offset + 3] = static_cast<std::uint8_t>(value >> 24);
}

void write_float(std::vector<std::uint8_t>& bytes, std::size_t offset, float value) {
  write_le32(bytes, offset, std::bit_cast<std::uint32_t>(value));
}

HighCommand sample_walk() {
  HighCommand command;
  command.mode = Mode::kVelocityWalk;
  command.gait_type = GaitType::kTrot;
  command.velocity = {0.2f, -0.1f};
  command.yaw_speed = 0.5f;
  command.body_height = -0.05f;
  return command;
}

// The library's encryptCRC (FACTS §1 "CRC": XOR 0xEDCAB9DE, then byte swaps (1,2), (0,3),
// (0,2)) moves byte k of the XORed value to byte k - 1: a rotation right by 8 bits. Written
// this way here, independently of crc_cipher.cpp's swaps.
std::uint32_t encrypted_by_rotation(std::uint32_t crc) {
  return std::rotr(crc ^ 0xEDCAB9DEu, 8);
}

std::string hex(std::uint32_t value) {
  char text[16];
  std::snprintf(text, sizeof text, "0x%08x", value);
  return text;
}

TEST(Go1Crc, EncryptionIsTheLibrarysRotationAndDecryptionUndoesIt) {
  std::uint32_t seed = 777;
  for (int i = 0; i < 1000; ++i) {
    seed = seed * 1103515245u + 12345u;
    const std::uint32_t crc = seed ^ (seed << 13);
    EXPECT_EQ(encrypt_crc(crc), encrypted_by_rotation(crc));
    EXPECT_EQ(decrypt_crc(encrypt_crc(crc)), crc);
    EXPECT_EQ(encrypt_crc(decrypt_crc(crc)), crc);
  }
  EXPECT_EQ(decrypt_crc(0x00000000u), 0xEDCAB9DEu);
  EXPECT_EQ(stored_crc(0x12345678u, CrcForm::kPlain), 0x12345678u);
}

TEST(Go1Crc, MpegCheckValueOfTheReferenceImplementation) {
  const std::string check = "123456789";
  EXPECT_EQ(crc32_mpeg2(std::vector<std::uint8_t>(check.begin(), check.end())), 0x0376E6E7u);
}

TEST(Go1Crc, EqualsMpegOverByteReversedWords) {
  std::vector<std::uint8_t> bytes(124);
  std::uint32_t seed = 12345;
  for (auto& byte : bytes) {
    seed = seed * 1103515245u + 12345u;
    byte = static_cast<std::uint8_t>(seed >> 16);
  }
  EXPECT_EQ(go1_crc32(bytes, 31), crc_by_mpeg2(bytes, 31));
  EXPECT_EQ(go1_crc32(bytes, 1), crc_by_mpeg2(bytes, 1));
}

TEST(Go1HighCmd, EncodesToTheDocumentedBytes) {
  std::vector<std::uint8_t> expected(129, 0);
  expected[0] = 0xFE;
  expected[1] = 0xEF;
  expected[2] = 0xEE;                                     // levelFlag HIGHLEVEL
  expected[22] = 2;                                       // mode: target-velocity walking
  expected[23] = 1;                                       // gaitType: trot
  write_float(expected, 29, -0.05f);                      // bodyHeight
  write_float(expected, 53, 0.2f);                        // velocity[0]
  write_float(expected, 57, -0.1f);                       // velocity[1]
  write_float(expected, 61, 0.5f);                        // yawSpeed
  write_le32(expected, 125, crc_by_mpeg2(expected, 31));  // crc of bytes 0..123

  const HighCmdBytes encoded = encode_high_cmd(sample_walk(), 0xEE);
  EXPECT_EQ(std::vector<std::uint8_t>(encoded.begin(), encoded.end()), expected);
}

TEST(Go1HighCmd, LevelFlagIsConfigurable) {
  const HighCmdBytes encoded = encode_high_cmd(sample_walk(), kLevelFlagZero);
  EXPECT_EQ(encoded[2], 0x00);
  EXPECT_TRUE(decode_high_cmd(encoded, kLevelFlagZero).ok());
  const auto refused = decode_high_cmd(encoded, kLevelFlagHighLevel);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.refused().reason, PacketRefusal::kWrongLevelFlag);
  EXPECT_TRUE(decode_high_cmd(encoded, std::nullopt).ok());
}

TEST(Go1HighCmd, RoundTrips) {
  HighCommand command = sample_walk();
  command.speed_level = 1;
  command.foot_raise_height = 0.02f;
  command.position = {1.5f, -2.5f};
  command.euler = {0.1f, -0.2f, 0.3f};
  const auto decoded = decode_high_cmd(encode_high_cmd(command, 0xEE), 0xEE);
  ASSERT_TRUE(decoded.ok()) << decoded.refused().detail;
  EXPECT_EQ(decoded.packet(), command);
}

TEST(Go1HighCmd, EveryFlippedCoveredByteIsRefusedByTheCrc) {
  const HighCmdBytes good = encode_high_cmd(sample_walk(), 0xEE);
  for (std::size_t i = 3; i < 129; ++i) {
    if (i == 124) continue;  // the one byte the SDK's CRC leaves uncovered (FACTS §1)
    HighCmdBytes bad = good;
    bad[i] ^= 0x01;
    const auto decoded = decode_high_cmd(bad, 0xEE);
    ASSERT_FALSE(decoded.ok()) << "byte " << i;
    EXPECT_EQ(decoded.refused().reason, PacketRefusal::kBadCrc) << "byte " << i;
  }
}

TEST(Go1HighCmd, TheUncoveredByteIsNotChecked) {
  HighCmdBytes packet = encode_high_cmd(sample_walk(), 0xEE);
  packet[124] ^= 0xFF;
  EXPECT_TRUE(decode_high_cmd(packet, 0xEE).ok());
}

TEST(Go1HighCmd, RefusesWrongLengthAndHeadWithAReason) {
  const HighCmdBytes good = encode_high_cmd(sample_walk(), 0xEE);
  const auto short_packet = decode_high_cmd(std::span(good).first(128), 0xEE);
  ASSERT_FALSE(short_packet.ok());
  EXPECT_EQ(short_packet.refused().reason, PacketRefusal::kWrongLength);
  EXPECT_EQ(short_packet.refused().detail, "length 128, expected 129");

  HighCmdBytes bad_head = good;
  bad_head[1] = 0xEE;
  const auto head = decode_high_cmd(bad_head, 0xEE);
  ASSERT_FALSE(head.ok());
  EXPECT_EQ(head.refused().reason, PacketRefusal::kWrongHead);
  EXPECT_EQ(refusal_name(head.refused().reason), "wrong head");

  const auto empty = decode_high_cmd({}, 0xEE);
  ASSERT_FALSE(empty.ok());
  EXPECT_EQ(empty.refused().reason, PacketRefusal::kWrongLength);
}

TEST(Go1HighState, FieldsSitAtTheDocumentedOffsetsAndRoundTrip) {
  HighState state;
  state.mode = Mode::kVelocityWalk;
  state.gait_type = GaitType::kTrot;
  state.position = {1.25f, -0.5f, 0.0f};
  state.velocity = {0.3f, 0.0f, 0.1f};
  state.yaw_speed = 0.1f;
  state.imu_rpy = {0.0f, 0.0f, 0.75f};
  state.battery_percent = 87;
  state.foot_force = {10, -20, 30, -40};
  state.body_height = 0.28f;
  const HighStateBytes bytes = encode_high_state(state, 0xEE);

  float value = 0.0f;
  std::memcpy(&value, &bytes[895], 4);  // position[0]; the test host is little-endian like the Go1
  EXPECT_EQ(value, 1.25f);
  std::memcpy(&value, &bytes[70], 4);  // imu.rpy[2]
  EXPECT_EQ(value, 0.75f);
  EXPECT_EQ(bytes[885], 2);   // mode
  EXPECT_EQ(bytes[838], 87);  // bms.SOC
  std::vector<std::uint8_t> all(bytes.begin(), bytes.end());
  EXPECT_EQ(bytes[1083] | bytes[1084] << 8 | bytes[1085] << 16 | std::uint32_t{bytes[1086]} << 24,
            encrypted_by_rotation(crc_by_mpeg2(all, 270)));

  const auto decoded = decode_high_state(bytes, 0xEE);
  ASSERT_TRUE(decoded.ok()) << decoded.refused().detail;
  EXPECT_EQ(decoded.packet(), state);
}

TEST(Go1HighState, FlippedByteIsRefusedUnlessTheCrcCheckIsOff) {
  HighStateBytes bytes = encode_high_state(HighState{}, 0xEE);
  bytes[900] ^= 0x40;
  const auto decoded = decode_high_state(bytes, 0xEE);
  ASSERT_FALSE(decoded.ok());
  EXPECT_EQ(decoded.refused().reason, PacketRefusal::kBadCrc);
  EXPECT_TRUE(decode_high_state(bytes, 0xEE, /*check_crc=*/false).ok());
}

// The robot's form (encrypted) and the developer-mode form (plain) are both read; a CRC in
// neither form is refused with both values the decoder tried.
TEST(Go1HighState, TheEncryptedAndThePlainCrcAreReadAndTheRefusalNamesBoth) {
  HighState state;
  state.position = {0.5f, 0.25f, 0.0f};
  const HighStateBytes robot = encode_high_state(state, 0xEE);
  const HighStateBytes developer = encode_high_state(state, 0xEE, CrcForm::kPlain);
  EXPECT_NE(robot, developer);
  for (const HighStateBytes& bytes : {robot, developer}) {
    const auto decoded = decode_high_state(bytes, 0xEE);
    ASSERT_TRUE(decoded.ok()) << decoded.refused().detail;
    EXPECT_EQ(decoded.packet(), state);
  }
  HighStateBytes neither = robot;
  neither[1083] ^= 0x01;
  const auto refused = decode_high_state(neither, 0xEE);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.refused().reason, PacketRefusal::kBadCrc);
  const std::vector<std::uint8_t> all(robot.begin(), robot.end());
  const std::uint32_t crc = crc_by_mpeg2(all, 270);
  EXPECT_NE(refused.refused().detail.find("encrypted " + hex(encrypted_by_rotation(crc))),
            std::string::npos)
      << refused.refused().detail;
  EXPECT_NE(refused.refused().detail.find("plain " + hex(crc)), std::string::npos)
      << refused.refused().detail;
}

// As Unitree's library reads them: a high-level (0xEE) HighState with the encrypted CRC, any
// other level flag with the plain one.
TEST(Go1HighState, TheCrcFormFollowsTheLevelFlagAsTheLibraryReadsIt) {
  EXPECT_EQ(robot_crc_form(0xEE), CrcForm::kEncrypted);
  EXPECT_EQ(robot_crc_form(0x00), CrcForm::kPlain);
  EXPECT_EQ(encode_high_state(HighState{}, 0x00),
            encode_high_state(HighState{}, 0x00, CrcForm::kPlain));
  EXPECT_TRUE(decode_high_state(encode_high_state(HighState{}, 0x00), 0x00).ok());
}

// A HighCmd carries the plain CRC (the library's SetSend(HighCmd&)): the encrypted form is
// refused there.
TEST(Go1HighCmd, OnlyThePlainCrcIsRead) {
  HighCmdBytes bytes = encode_high_cmd(sample_walk(), 0xEE);
  std::uint32_t stored = 0;
  std::memcpy(&stored, &bytes[125], 4);
  const std::uint32_t encrypted = encrypt_crc(stored);
  std::memcpy(&bytes[125], &encrypted, 4);
  const auto decoded = decode_high_cmd(bytes, 0xEE);
  ASSERT_FALSE(decoded.ok());
  EXPECT_EQ(decoded.refused().reason, PacketRefusal::kBadCrc);
}

}  // namespace
}  // namespace oasis::hw::go1
