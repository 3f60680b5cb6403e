#pragma once
// The high-level command packet, HighCmd: 129 bytes (FACTS §1 "HighCmd"). Only the fields a
// high-level client sets are modelled; SN, version, bandWidth, the battery command, the LEDs,
// wirelessRemote and reserve are always sent as zero (a battery byte of 0xA5 would switch the
// robot off, so it is deliberately not exposed).

#include <array>
#include <cstdint>
#include <optional>
#include <span>

#include "go1/packet_refusal.hpp"
#include "go1/protocol.hpp"

namespace oasis::hw::go1 {

struct HighCommand {
  Mode mode = Mode::kIdle;
  GaitType gait_type = GaitType::kIdle;
  std::uint8_t speed_level = 0;
  float foot_raise_height = 0.0f;   // m, delta from the default
  float body_height = 0.0f;         // m, delta from the default
  std::array<float, 2> position{};  // target-position walking (reserve)
  std::array<float, 3> euler{};     // rad, roll pitch yaw in force-stand mode
  std::array<float, 2> velocity{};  // m/s, forward and lateral, body frame
  float yaw_speed = 0.0f;           // rad/s

  bool operator==(const HighCommand&) const = default;
};

// Field offsets in the packet (FACTS §1, from offsetof on the SDK's packed struct).
namespace high_cmd_offset {
inline constexpr std::size_t kMode = 22;
inline constexpr std::size_t kGaitType = 23;
inline constexpr std::size_t kSpeedLevel = 24;
inline constexpr std::size_t kFootRaiseHeight = 25;
inline constexpr std::size_t kBodyHeight = 29;
inline constexpr std::size_t kPosition = 33;
inline constexpr std::size_t kEuler = 41;
inline constexpr std::size_t kVelocity = 53;
inline constexpr std::size_t kYawSpeed = 61;
inline constexpr std::size_t kCrc = 125;
}  // namespace high_cmd_offset

using HighCmdBytes = std::array<std::uint8_t, kHighCmdLength>;

HighCmdBytes encode_high_cmd(const HighCommand& command, std::uint8_t level_flag);

// Refuses a packet of the wrong length or head, with another level flag than
// `expected_level_flag` (unless nullopt), or whose CRC does not match.
DecodeResult<HighCommand> decode_high_cmd(std::span<const std::uint8_t> packet,
                                          std::optional<std::uint8_t> expected_level_flag);

}  // namespace oasis::hw::go1
