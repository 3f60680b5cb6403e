#pragma once
// The high-level state packet, HighState: 1087 bytes (FACTS §1 "HighState"). The fields a
// high-level client reads are modelled; the motor states, battery detail other than the charge,
// foot positions and speeds and wirelessRemote are skipped on decode and written as zero on encode
// (the fake Go1 is the only encoder).

#include <array>
#include <cstdint>
#include <optional>
#include <span>

#include "go1/crc_cipher.hpp"
#include "go1/packet_refusal.hpp"
#include "go1/protocol.hpp"

namespace oasis::hw::go1 {

struct HighState {
  std::array<float, 4> imu_quaternion{1.0f, 0.0f, 0.0f, 0.0f};  // w, x, y, z
  std::array<float, 3> imu_gyroscope{};                         // rad/s
  std::array<float, 3> imu_accelerometer{};                     // m/s^2
  std::array<float, 3> imu_rpy{};                               // rad, roll pitch yaw
  std::int8_t imu_temperature = 0;
  std::uint8_t battery_percent = 0;  // BmsState.SOC
  std::array<std::int16_t, 4> foot_force{};
  Mode mode = Mode::kIdle;
  float progress = 0.0f;
  GaitType gait_type = GaitType::kIdle;
  float foot_raise_height = 0.0f;
  std::array<float, 3> position{};  // m, odometry; drifts (comm.h)
  float body_height = 0.0f;         // m
  std::array<float, 3> velocity{};  // forward, side (m/s) and rotation speed, body frame
  float yaw_speed = 0.0f;           // rad/s
  std::array<float, 4> range_obstacle{};

  bool operator==(const HighState&) const = default;
};

namespace high_state_offset {
inline constexpr std::size_t kImuQuaternion = 22;
inline constexpr std::size_t kImuGyroscope = 38;
inline constexpr std::size_t kImuAccelerometer = 50;
inline constexpr std::size_t kImuRpy = 62;
inline constexpr std::size_t kImuTemperature = 74;
inline constexpr std::size_t kBatteryPercent = 838;
inline constexpr std::size_t kFootForce = 869;
inline constexpr std::size_t kMode = 885;
inline constexpr std::size_t kProgress = 886;
inline constexpr std::size_t kGaitType = 890;
inline constexpr std::size_t kFootRaiseHeight = 891;
inline constexpr std::size_t kPosition = 895;
inline constexpr std::size_t kBodyHeight = 907;
inline constexpr std::size_t kVelocity = 911;
inline constexpr std::size_t kYawSpeed = 923;
inline constexpr std::size_t kRangeObstacle = 927;
inline constexpr std::size_t kCrc = 1083;
}  // namespace high_state_offset

using HighStateBytes = std::array<std::uint8_t, kHighStateLength>;

// The CRC form Unitree's library checks a HighState with: encrypted when the level flag is 0xEE
// (high level, as the robot sends it), plain otherwise (UDP::Recv()).
CrcForm robot_crc_form(std::uint8_t level_flag);

// Without `crc_form`, the CRC is stored as the robot stores it (robot_crc_form()); kPlain
// writes what a developer-mode peer sends.
HighStateBytes encode_high_state(const HighState& state, std::uint8_t level_flag,
                                 std::optional<CrcForm> crc_form = std::nullopt);

// With `check_crc`, the CRC must be stored encrypted (as the robot sends it) or plain (as
// Unitree's library also accepts in its developer mode); the refusal names both values tried.
// Without it, the CRC is not looked at.
DecodeResult<HighState> decode_high_state(std::span<const std::uint8_t> packet,
                                          std::optional<std::uint8_t> expected_level_flag,
                                          bool check_crc = true);

}  // namespace oasis::hw::go1
