#include "go1/high_state.hpp"

#include "go1/byte_order.hpp"
#include "go1/packet_frame.hpp"

namespace oasis::hw::go1 {

namespace o = high_state_offset;

namespace {

template <std::size_t N>
void put_floats(std::span<std::uint8_t> packet, std::size_t offset,
                const std::array<float, N>& values) {
  for (std::size_t i = 0; i < N; ++i)
    put_f32(packet, offset + 4 * i, values[i]);
}

template <std::size_t N>
void get_floats(std::span<const std::uint8_t> packet, std::size_t offset,
                std::array<float, N>& values) {
  for (std::size_t i = 0; i < N; ++i)
    values[i] = get_f32(packet, offset + 4 * i);
}

}  // namespace

CrcForm robot_crc_form(std::uint8_t level_flag) {
  return level_flag == kLevelFlagHighLevel ? CrcForm::kEncrypted : CrcForm::kPlain;
}

HighStateBytes encode_high_state(const HighState& state, std::uint8_t level_flag,
                                 std::optional<CrcForm> crc_form) {
  HighStateBytes packet{};
  put_floats(packet, o::kImuQuaternion, state.imu_quaternion);
  put_floats(packet, o::kImuGyroscope, state.imu_gyroscope);
  put_floats(packet, o::kImuAccelerometer, state.imu_accelerometer);
  put_floats(packet, o::kImuRpy, state.imu_rpy);
  put_u8(packet, o::kImuTemperature, static_cast<std::uint8_t>(state.imu_temperature));
  put_u8(packet, o::kBatteryPercent, state.battery_percent);
  for (std::size_t i = 0; i < 4; ++i)
    put_i16(packet, o::kFootForce + 2 * i, state.foot_force[i]);
  put_u8(packet, o::kMode, static_cast<std::uint8_t>(state.mode));
  put_f32(packet, o::kProgress, state.progress);
  put_u8(packet, o::kGaitType, static_cast<std::uint8_t>(state.gait_type));
  put_f32(packet, o::kFootRaiseHeight, state.foot_raise_height);
  put_floats(packet, o::kPosition, state.position);
  put_f32(packet, o::kBodyHeight, state.body_height);
  put_floats(packet, o::kVelocity, state.velocity);
  put_f32(packet, o::kYawSpeed, state.yaw_speed);
  put_floats(packet, o::kRangeObstacle, state.range_obstacle);
  seal_frame(packet, level_flag, crc_form.value_or(robot_crc_form(level_flag)));
  return packet;
}

DecodeResult<HighState> decode_high_state(std::span<const std::uint8_t> packet,
                                          std::optional<std::uint8_t> expected_level_flag,
                                          bool check_crc) {
  const AcceptedCrcForms robot_or_developer{CrcForm::kEncrypted, CrcForm::kPlain};
  if (auto refused = check_frame(packet, kHighStateLength, expected_level_flag,
                                 check_crc ? robot_or_developer : AcceptedCrcForms{}))
    return *refused;
  HighState state;
  get_floats(packet, o::kImuQuaternion, state.imu_quaternion);
  get_floats(packet, o::kImuGyroscope, state.imu_gyroscope);
  get_floats(packet, o::kImuAccelerometer, state.imu_accelerometer);
  get_floats(packet, o::kImuRpy, state.imu_rpy);
  state.imu_temperature = static_cast<std::int8_t>(packet[o::kImuTemperature]);
  state.battery_percent = packet[o::kBatteryPercent];
  for (std::size_t i = 0; i < 4; ++i)
    state.foot_force[i] = get_i16(packet, o::kFootForce + 2 * i);
  state.mode = static_cast<Mode>(packet[o::kMode]);
  state.progress = get_f32(packet, o::kProgress);
  state.gait_type = static_cast<GaitType>(packet[o::kGaitType]);
  state.foot_raise_height = get_f32(packet, o::kFootRaiseHeight);
  get_floats(packet, o::kPosition, state.position);
  state.body_height = get_f32(packet, o::kBodyHeight);
  get_floats(packet, o::kVelocity, state.velocity);
  state.yaw_speed = get_f32(packet, o::kYawSpeed);
  get_floats(packet, o::kRangeObstacle, state.range_obstacle);
  return state;
}

}  // namespace oasis::hw::go1
