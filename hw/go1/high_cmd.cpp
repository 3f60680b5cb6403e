#include "go1/high_cmd.hpp"

#include "go1/byte_order.hpp"
#include "go1/packet_frame.hpp"

namespace oasis::hw::go1 {

namespace o = high_cmd_offset;

HighCmdBytes encode_high_cmd(const HighCommand& command, std::uint8_t level_flag) {
  HighCmdBytes packet{};
  put_u8(packet, o::kMode, static_cast<std::uint8_t>(command.mode));
  put_u8(packet, o::kGaitType, static_cast<std::uint8_t>(command.gait_type));
  put_u8(packet, o::kSpeedLevel, command.speed_level);
  put_f32(packet, o::kFootRaiseHeight, command.foot_raise_height);
  put_f32(packet, o::kBodyHeight, command.body_height);
  for (std::size_t i = 0; i < 2; ++i)
    put_f32(packet, o::kPosition + 4 * i, command.position[i]);
  for (std::size_t i = 0; i < 3; ++i)
    put_f32(packet, o::kEuler + 4 * i, command.euler[i]);
  for (std::size_t i = 0; i < 2; ++i)
    put_f32(packet, o::kVelocity + 4 * i, command.velocity[i]);
  put_f32(packet, o::kYawSpeed, command.yaw_speed);
  seal_frame(packet, level_flag, CrcForm::kPlain);  // SetSend(HighCmd&): plain
  return packet;
}

DecodeResult<HighCommand> decode_high_cmd(std::span<const std::uint8_t> packet,
                                          std::optional<std::uint8_t> expected_level_flag) {
  if (auto refused = check_frame(packet, kHighCmdLength, expected_level_flag, {CrcForm::kPlain}))
    return *refused;
  HighCommand command;
  command.mode = static_cast<Mode>(packet[o::kMode]);
  command.gait_type = static_cast<GaitType>(packet[o::kGaitType]);
  command.speed_level = packet[o::kSpeedLevel];
  command.foot_raise_height = get_f32(packet, o::kFootRaiseHeight);
  command.body_height = get_f32(packet, o::kBodyHeight);
  for (std::size_t i = 0; i < 2; ++i)
    command.position[i] = get_f32(packet, o::kPosition + 4 * i);
  for (std::size_t i = 0; i < 3; ++i)
    command.euler[i] = get_f32(packet, o::kEuler + 4 * i);
  for (std::size_t i = 0; i < 2; ++i)
    command.velocity[i] = get_f32(packet, o::kVelocity + 4 * i);
  command.yaw_speed = get_f32(packet, o::kYawSpeed);
  return command;
}

}  // namespace oasis::hw::go1
