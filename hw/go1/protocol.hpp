#pragma once
// Constants of the Go1 high-level protocol (FACTS §1). Values marked "unconfirmed" in FACTS
// (the level flag the current firmware wants, the local port) are defaults only: every user
// of them takes them from a configuration.

#include <cstddef>
#include <cstdint>

namespace oasis::hw::go1 {

inline constexpr std::size_t kHighCmdLength = 129;
inline constexpr std::size_t kHighStateLength = 1087;
inline constexpr std::uint8_t kHead0 = 0xFE;
inline constexpr std::uint8_t kHead1 = 0xEF;

// Byte 2 of every packet. The SDK writes 0xEE (HIGHLEVEL); free-dog-sdk writes 0x00 and one user
// reports the Go1 obeyed only with 0x00. Which one current firmware needs is not confirmed.
inline constexpr std::uint8_t kLevelFlagHighLevel = 0xEE;
inline constexpr std::uint8_t kLevelFlagZero = 0x00;

// The SDK's high-level ("sport") target and its C++ example's local port (8080 in the Python one).
inline constexpr const char* kRobotAddress = "192.168.123.161";
inline constexpr std::uint16_t kRobotPort = 8082;
inline constexpr std::uint16_t kDefaultLocalPort = 8090;

// HighCmd.mode (comm.h comments). Only the values this library commands or recognises are named.
enum class Mode : std::uint8_t {
  kIdle = 0,           // idle, default stand: what we send to "stand"
  kForceStand = 1,     // stand with bodyHeight and euler
  kVelocityWalk = 2,   // target-velocity walking: what we send to drive and, at zero, to "stop"
  kStandDown = 5,      // position stand down
  kStandUp = 6,        // position stand up
  kDamping = 7,        // damping
  kRecoveryStand = 8,  // recovery stand
};

enum class GaitType : std::uint8_t {
  kIdle = 0,
  kTrot = 1,
  kTrotRunning = 2,
  kClimbStair = 3,
  kTrotObstacle = 4
};

}  // namespace oasis::hw::go1
