// Our Go1 link against Unitree's own client library (unitree_legged_sdk, branch go1), the two
// talking over loopback (README.md here):
//   LibraryLayout     comm.h's packed structs have our lengths and field offsets;
//   LibraryHighCmd    the bytes the library's UDP::Send() puts on the wire equal encode_high_cmd's
//                     for every command the sender makes (stand, stop and walking in each gait,
//                     turning, the limits' extremes), with both level flags, and
//                     decode_high_cmd reads them back;
//   SenderOnTheWire   what our Sender sends (stand, then the ramp settled at the clamped command,
//                     then stop and stand on shutdown) equals the library's bytes for those fields;
//   LibraryReadsState which CRC form the library's UDP::Recv() accepts for which level flag, and
//                     that it reads every field encode_high_state writes where comm.h has it;
//   LibraryClient     the library's client, sending at 500 Hz as its example_walk.cpp does, reads
//                     the FakeGo1's HighStates with no CRC error and sees the commanded motion.
//
// Each case is its own process (ctest) with its own sockets on 127.0.0.1, any free port. The
// library's UDP binds 0.0.0.0 with the port given (0: any free one) and connects to its target,
// so it hears only from that address and port.

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <iomanip>
#include <optional>
#include <span>
#include <sstream>
#include <string>
#include <thread>
#include <tuple>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <unitree_legged_sdk/comm.h>
#include <unitree_legged_sdk/udp.h>

#include "go1/crc_cipher.hpp"
#include "go1/endpoint.hpp"
#include "go1/fake_go1.hpp"
#include "go1/high_cmd.hpp"
#include "go1/high_state.hpp"
#include "go1/protocol.hpp"
#include "go1/sender.hpp"
#include "go1/udp_socket.hpp"

namespace oasis::hw::go1 {
namespace {

namespace sdk = UNITREE_LEGGED_SDK;
using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;
using Bytes = std::vector<std::uint8_t>;

// The library keeps this pointer (UDP::targetIP), so it must be of static storage.
constexpr const char* kLoopback = "127.0.0.1";
constexpr std::uint8_t kLibraryHighLevel = static_cast<std::uint8_t>(sdk::HIGHLEVEL);
constexpr milliseconds kArrival{1000};  // loopback delivers at once; this only bounds a failure

// --- The library's packed structs, read and written at offsetof --------------------------------
// A std::array member of a #pragma pack(1) struct sits at an odd offset, and calling its
// operator[] would be a misaligned member call (UBSan, in the asan preset, stops on it). So arrays
// go through memcpy at the library's own offsetof; scalar members are used directly.

template <typename Value, typename Packed>
Value read_at(const Packed& packed, std::size_t offset) {
  Value value{};
  std::memcpy(&value, reinterpret_cast<const unsigned char*>(&packed) + offset, sizeof value);
  return value;
}

template <typename Packed, typename Value>
void write_at(Packed& packed, std::size_t offset, const Value& value) {
  std::memcpy(reinterpret_cast<unsigned char*>(&packed) + offset, &value, sizeof value);
}

template <typename Packed>
Bytes bytes_of(const Packed& packed) {
  const auto* first = reinterpret_cast<const std::uint8_t*>(&packed);
  return Bytes(first, first + sizeof packed);
}

// The HighCmd a library user writes for `command`: InitCmdData (head FE EF, level flag 0xEE), then
// each field by its comm.h name. The library itself only writes 0xEE (its HIGHLEVEL, the only
// high-level flag its constructor takes); for 0x00, as free-dog-sdk sends, the user overwrites
// levelFlag, and SetSend computes the CRC over it.
sdk::HighCmd library_command(sdk::UDP& client, const HighCommand& command,
                             std::uint8_t level_flag) {
  sdk::HighCmd cmd{};
  client.InitCmdData(cmd);
  if (level_flag != kLibraryHighLevel) cmd.levelFlag = level_flag;
  cmd.mode = static_cast<std::uint8_t>(command.mode);
  cmd.gaitType = static_cast<std::uint8_t>(command.gait_type);
  cmd.speedLevel = command.speed_level;
  cmd.footRaiseHeight = command.foot_raise_height;
  cmd.bodyHeight = command.body_height;
  write_at(cmd, offsetof(sdk::HighCmd, position), command.position);
  write_at(cmd, offsetof(sdk::HighCmd, euler), command.euler);
  write_at(cmd, offsetof(sdk::HighCmd, velocity), command.velocity);
  cmd.yawSpeed = command.yaw_speed;
  return cmd;
}

// What the library received, by comm.h's field names, in our type.
HighState from_library(const sdk::HighState& state) {
  const std::size_t imu = offsetof(sdk::HighState, imu);
  HighState out;
  out.imu_quaternion = read_at<std::array<float, 4>>(state, imu + offsetof(sdk::IMU, quaternion));
  out.imu_gyroscope = read_at<std::array<float, 3>>(state, imu + offsetof(sdk::IMU, gyroscope));
  out.imu_accelerometer =
      read_at<std::array<float, 3>>(state, imu + offsetof(sdk::IMU, accelerometer));
  out.imu_rpy = read_at<std::array<float, 3>>(state, imu + offsetof(sdk::IMU, rpy));
  out.imu_temperature = state.imu.temperature;
  out.battery_percent = state.bms.SOC;
  out.foot_force = read_at<std::array<std::int16_t, 4>>(state, offsetof(sdk::HighState, footForce));
  out.mode = static_cast<Mode>(state.mode);
  out.progress = state.progress;
  out.gait_type = static_cast<GaitType>(state.gaitType);
  out.foot_raise_height = state.footRaiseHeight;
  out.position = read_at<std::array<float, 3>>(state, offsetof(sdk::HighState, position));
  out.body_height = state.bodyHeight;
  out.velocity = read_at<std::array<float, 3>>(state, offsetof(sdk::HighState, velocity));
  out.yaw_speed = state.yawSpeed;
  out.range_obstacle =
      read_at<std::array<float, 4>>(state, offsetof(sdk::HighState, rangeObstacle));
  return out;
}

// "" when the packets are equal, else each differing byte (the first 16) with both values.
std::string byte_differences(std::span<const std::uint8_t> ours,
                             std::span<const std::uint8_t> library) {
  std::ostringstream out;
  if (ours.size() != library.size())
    out << "length: ours " << ours.size() << ", library " << library.size() << "\n";
  std::size_t differing = 0;
  for (std::size_t i = 0; i < std::min(ours.size(), library.size()); ++i) {
    if (ours[i] == library[i]) continue;
    if (++differing <= 16)
      out << "  byte " << i << ": ours 0x" << std::hex << std::setw(2) << std::setfill('0')
          << unsigned{ours[i]} << ", library 0x" << std::setw(2) << unsigned{library[i]} << std::dec
          << "\n";
  }
  if (differing > 16) out << "  ... and " << differing - 16 << " more bytes differ\n";
  return out.str();
}

std::string describe(std::span<const std::uint8_t> packet) {
  const DecodeResult<HighCommand> decoded = decode_high_cmd(packet, std::nullopt);
  if (!decoded.ok()) return "a packet we refuse: " + decoded.refused().detail;
  const HighCommand& c = decoded.packet();
  std::ostringstream out;
  out << "mode " << int{static_cast<std::uint8_t>(c.mode)} << " gait "
      << int{static_cast<std::uint8_t>(c.gait_type)} << " velocity (" << c.velocity[0] << ", "
      << c.velocity[1] << ") yaw " << c.yaw_speed;
  return out.str();
}

// Unitree's client pointed at a loopback socket of ours: bytes() is what UDP::Send() puts on
// the wire for a command.
class LibraryCapture {
 public:
  LibraryCapture()
      : capture_(Endpoint{kLoopback, 0}),
        client_(kLibraryHighLevel, 0, kLoopback, capture_.local_endpoint().port) {}

  std::optional<Bytes> bytes(const HighCommand& command, std::uint8_t level_flag) {
    sdk::HighCmd cmd = library_command(client_, command, level_flag);
    client_.SetSend(cmd);
    if (client_.Send() != static_cast<int>(kHighCmdLength)) return std::nullopt;
    std::optional<Datagram> datagram = capture_.receive(kArrival);
    if (!datagram) return std::nullopt;
    return std::move(datagram->bytes);
  }

 private:
  UdpSocket capture_;
  sdk::UDP client_;
};

HighCommand walking(GaitType gait, float forward, float lateral, float yaw_rate) {
  HighCommand command;  // what Sender::walk() builds
  command.mode = Mode::kVelocityWalk;
  command.gait_type = gait;
  command.velocity = {forward, lateral};
  command.yaw_speed = yaw_rate;
  return command;
}

// --- Layout -------------------------------------------------------------------------------------

TEST(LibraryLayout, LengthsAndOffsetsAreOurs) {
  EXPECT_EQ(sizeof(sdk::HighCmd), kHighCmdLength);
  EXPECT_EQ(sizeof(sdk::HighState), kHighStateLength);
  EXPECT_EQ(static_cast<std::size_t>(sdk::HIGH_CMD_LENGTH), kHighCmdLength);
  EXPECT_EQ(static_cast<std::size_t>(sdk::HIGH_STATE_LENGTH), kHighStateLength);

  namespace c = high_cmd_offset;
  EXPECT_EQ(offsetof(sdk::HighCmd, mode), c::kMode);
  EXPECT_EQ(offsetof(sdk::HighCmd, gaitType), c::kGaitType);
  EXPECT_EQ(offsetof(sdk::HighCmd, speedLevel), c::kSpeedLevel);
  EXPECT_EQ(offsetof(sdk::HighCmd, footRaiseHeight), c::kFootRaiseHeight);
  EXPECT_EQ(offsetof(sdk::HighCmd, bodyHeight), c::kBodyHeight);
  EXPECT_EQ(offsetof(sdk::HighCmd, position), c::kPosition);
  EXPECT_EQ(offsetof(sdk::HighCmd, euler), c::kEuler);
  EXPECT_EQ(offsetof(sdk::HighCmd, velocity), c::kVelocity);
  EXPECT_EQ(offsetof(sdk::HighCmd, yawSpeed), c::kYawSpeed);
  EXPECT_EQ(offsetof(sdk::HighCmd, crc), c::kCrc);

  namespace s = high_state_offset;
  const std::size_t imu = offsetof(sdk::HighState, imu);
  EXPECT_EQ(imu + offsetof(sdk::IMU, quaternion), s::kImuQuaternion);
  EXPECT_EQ(imu + offsetof(sdk::IMU, gyroscope), s::kImuGyroscope);
  EXPECT_EQ(imu + offsetof(sdk::IMU, accelerometer), s::kImuAccelerometer);
  EXPECT_EQ(imu + offsetof(sdk::IMU, rpy), s::kImuRpy);
  EXPECT_EQ(imu + offsetof(sdk::IMU, temperature), s::kImuTemperature);
  EXPECT_EQ(offsetof(sdk::HighState, bms) + offsetof(sdk::BmsState, SOC), s::kBatteryPercent);
  EXPECT_EQ(offsetof(sdk::HighState, footForce), s::kFootForce);
  EXPECT_EQ(offsetof(sdk::HighState, mode), s::kMode);
  EXPECT_EQ(offsetof(sdk::HighState, progress), s::kProgress);
  EXPECT_EQ(offsetof(sdk::HighState, gaitType), s::kGaitType);
  EXPECT_EQ(offsetof(sdk::HighState, footRaiseHeight), s::kFootRaiseHeight);
  EXPECT_EQ(offsetof(sdk::HighState, position), s::kPosition);
  EXPECT_EQ(offsetof(sdk::HighState, bodyHeight), s::kBodyHeight);
  EXPECT_EQ(offsetof(sdk::HighState, velocity), s::kVelocity);
  EXPECT_EQ(offsetof(sdk::HighState, yawSpeed), s::kYawSpeed);
  EXPECT_EQ(offsetof(sdk::HighState, rangeObstacle), s::kRangeObstacle);
  EXPECT_EQ(offsetof(sdk::HighState, crc), s::kCrc);
}

// --- 1. HighCmd bytes: the library's against encode_high_cmd -----------------------------------

struct NamedCommand {
  std::string name;
  HighCommand command;
};

// Every command Sender makes (sender.cpp: stand_command() and walk(), whose gait is the
// configured one, any of the five), and one with every field encode_high_cmd writes.
std::vector<NamedCommand> commands_we_send() {
  std::vector<NamedCommand> commands;
  commands.push_back({"stand", HighCommand{}});  // stand_command(): idle mode and gait, all zero
  const std::vector<std::pair<std::string, GaitType>> gaits = {
      {"idle", GaitType::kIdle},
      {"trot", GaitType::kTrot},
      {"trot_running", GaitType::kTrotRunning},
      {"climb_stair", GaitType::kClimbStair},
      {"trot_obstacle", GaitType::kTrotObstacle}};
  for (const auto& [name, gait] : gaits) {
    commands.push_back({"stop_" + name, walking(gait, 0.0f, 0.0f, 0.0f)});
    commands.push_back({"walk_" + name, walking(gait, 0.4f, 0.0f, 0.0f)});
  }
  commands.push_back({"turn_left", walking(GaitType::kTrot, 0.0f, 0.0f, 1.0f)});
  commands.push_back({"turn_right_walking", walking(GaitType::kTrot, 0.5f, 0.0f, -0.5f)});
  commands.push_back({"back_and_sideways", walking(GaitType::kTrot, -0.3f, 0.3f, 0.0f)});
  // Values a ramp passes through (multiples of its per-tick step), nothing round in binary.
  commands.push_back(
      {"mid_ramp", walking(GaitType::kTrot, 0.002f * 37.0f, -0.002f * 11.0f, 0.006f * 23.0f)});
  HighCommand every_field;
  every_field.mode = Mode::kForceStand;
  every_field.gait_type = GaitType::kTrotRunning;
  every_field.speed_level = 2;
  every_field.foot_raise_height = -0.03f;
  every_field.body_height = 0.02f;
  every_field.position = {1.25f, -2.5f};
  every_field.euler = {0.1f, -0.2f, 0.3f};
  every_field.velocity = {0.7f, -0.6f};
  every_field.yaw_speed = -3.5f;
  commands.push_back({"every_field", every_field});
  return commands;
}

class LibraryHighCmd : public ::testing::TestWithParam<std::tuple<NamedCommand, std::uint8_t>> {};

TEST_P(LibraryHighCmd, BytesEqualOurs) {
  const auto& [named, level_flag] = GetParam();
  LibraryCapture library;
  const std::optional<Bytes> sent = library.bytes(named.command, level_flag);
  ASSERT_TRUE(sent.has_value()) << "nothing arrived from the library's UDP::Send()";

  const HighCmdBytes ours = encode_high_cmd(named.command, level_flag);
  EXPECT_EQ(byte_differences(ours, *sent), "");

  const DecodeResult<HighCommand> decoded = decode_high_cmd(*sent, level_flag);
  ASSERT_TRUE(decoded.ok()) << "we refuse the library's packet: " << decoded.refused().detail;
  EXPECT_TRUE(decoded.packet() == named.command) << "decoded " << describe(*sent);
}

INSTANTIATE_TEST_SUITE_P(Commands, LibraryHighCmd,
                         ::testing::Combine(::testing::ValuesIn(commands_we_send()),
                                            ::testing::Values(kLevelFlagHighLevel, kLevelFlagZero)),
                         [](const ::testing::TestParamInfo<LibraryHighCmd::ParamType>& param_info) {
                           const std::uint8_t level_flag = std::get<1>(param_info.param);
                           return std::get<0>(param_info.param).name +
                                  (level_flag == kLevelFlagHighLevel ? "_flag_ee" : "_flag_00");
                         });

// --- 2. Our Sender on the wire against the library -----------------------------------------------

struct SenderCase {
  std::string name;
  std::uint8_t level_flag;
  GaitType gait;
  VelocityCommand wanted;   // what the program asks for
  VelocityCommand settled;  // after the default limits' clamp (motion_limits.hpp)
};

// Receives every packet that arrives within `duration` into `wire`.
void receive_for(UdpSocket& socket, milliseconds duration, std::vector<Bytes>& wire) {
  const Clock::time_point end = Clock::now() + duration;
  for (Clock::time_point now = Clock::now(); now < end; now = Clock::now()) {
    const auto left = std::chrono::duration_cast<milliseconds>(end - now) + milliseconds(1);
    if (std::optional<Datagram> datagram = socket.receive(left))
      wire.push_back(std::move(datagram->bytes));
  }
}

// Consecutive equal packets as one.
std::vector<Bytes> runs(const std::vector<Bytes>& packets) {
  std::vector<Bytes> distinct;
  for (const Bytes& packet : packets)
    if (distinct.empty() || distinct.back() != packet) distinct.push_back(packet);
  return distinct;
}

class SenderOnTheWire : public ::testing::TestWithParam<SenderCase> {};

TEST_P(SenderOnTheWire, StandSettledRampStopAndStandEqualTheLibrarys) {
  const SenderCase& given = GetParam();
  const HighCommand settled =
      walking(given.gait, given.settled.forward, given.settled.lateral, given.settled.yaw_rate);
  LibraryCapture library;
  const std::optional<Bytes> library_stand = library.bytes(HighCommand{}, given.level_flag);
  const std::optional<Bytes> library_walk = library.bytes(settled, given.level_flag);
  const std::optional<Bytes> library_stop =
      library.bytes(walking(given.gait, 0.0f, 0.0f, 0.0f), given.level_flag);
  ASSERT_TRUE(library_stand && library_walk && library_stop) << "the library sent nothing";

  UdpSocket robot(Endpoint{kLoopback, 0});  // stands in for the Go1: only listens
  SenderOptions options;                    // the defaults: 500 Hz, the default limits and ramp
  options.robot = robot.local_endpoint();
  options.local = Endpoint{kLoopback, 0};
  options.level_flag = given.level_flag;
  options.gait = given.gait;
  options.stop_hold = milliseconds(20);
  options.shutdown_stand_hold = milliseconds(20);
  options.obey_stop_signal = false;

  std::vector<Bytes> wire;
  std::size_t driving_end = 0;  // packets received before stop()
  {
    Sender sender(options);
    receive_for(robot, milliseconds(20), wire);  // stand, before the first command
    // The ramp takes 0.5 s at the default 1 m/s^2 to 0.5 m/s; settled: 20 packets in a row
    // equal to the library's.
    const Clock::time_point give_up = Clock::now() + std::chrono::seconds(3);
    std::size_t in_a_row = 0;
    while (in_a_row < 20 && Clock::now() < give_up) {
      sender.set_command(given.wanted);
      const std::size_t before = wire.size();
      receive_for(robot, milliseconds(10), wire);
      for (std::size_t i = before; i < wire.size(); ++i)
        in_a_row = wire[i] == *library_walk ? in_a_row + 1 : 0;
    }
    driving_end = wire.size();
    sender.stop();  // stop for stop_hold, then stand for shutdown_stand_hold
    EXPECT_EQ(sender.status().send_failures, 0u) << sender.status().last_send_error;
  }
  receive_for(robot, milliseconds(50), wire);

  ASSERT_FALSE(wire.empty()) << "the sender sent nothing";
  EXPECT_EQ(byte_differences(wire.front(), *library_stand), "")
      << "first packet (stand): " << describe(wire.front());
  std::size_t first_settled = 0;
  while (first_settled < wire.size() && wire[first_settled] != *library_walk)
    ++first_settled;
  const Bytes& last_driving = wire[driving_end > 0 ? driving_end - 1 : 0];
  ASSERT_LT(first_settled, wire.size())
      << "never the library's bytes for " << describe(*library_walk)
      << "; the last sent while driving: " << describe(last_driving) << "\n"
      << byte_differences(last_driving, *library_walk);

  const std::vector<Bytes> after(wire.begin() + static_cast<std::ptrdiff_t>(first_settled),
                                 wire.end());
  const std::vector<Bytes> sequence = runs(after);
  ASSERT_EQ(sequence.size(), 3u) << "expected walk, stop, stand after settling; got "
                                 << sequence.size() << " distinct runs, the last "
                                 << describe(sequence.back());
  EXPECT_EQ(byte_differences(sequence[0], *library_walk), "");
  EXPECT_EQ(byte_differences(sequence[1], *library_stop), "") << describe(sequence[1]);
  EXPECT_EQ(byte_differences(sequence[2], *library_stand), "") << describe(sequence[2]);
}

INSTANTIATE_TEST_SUITE_P(
    Settled, SenderOnTheWire,
    ::testing::Values(
        // Beyond every limit: forward 0.5, lateral 0.3, yaw 1.0 (the defaults).
        SenderCase{"clamped_trot_flag_ee", kLevelFlagHighLevel, GaitType::kTrot,
                   VelocityCommand{5.0f, -2.0f, 3.0f}, VelocityCommand{0.5f, -0.3f, 1.0f}},
        // Backward clamped to 0.3; lateral and yaw inside the limits, not round in binary.
        SenderCase{"backward_climb_stair_flag_00", kLevelFlagZero, GaitType::kClimbStair,
                   VelocityCommand{-4.0f, 0.1f, -0.2f}, VelocityCommand{-0.3f, 0.1f, -0.2f}}),
    [](const ::testing::TestParamInfo<SenderCase>& param_info) { return param_info.param.name; });

// --- The library's receive rule, and every HighState field ---------------------------------------

struct CrcRuleCase {
  std::string name;
  std::uint8_t level_flag;
  CrcForm form;
  bool library_reads;
};

// A HighState with every field encode_high_state writes set to something distinct.
HighState distinct_state() {
  HighState state;
  state.imu_quaternion = {0.9f, 0.1f, -0.2f, 0.3f};
  state.imu_gyroscope = {0.01f, -0.02f, 0.03f};
  state.imu_accelerometer = {0.1f, 0.2f, 9.81f};
  state.imu_rpy = {0.05f, -0.06f, 1.5f};
  state.imu_temperature = -7;
  state.battery_percent = 87;
  state.foot_force = {120, -3, 456, 32000};
  state.mode = Mode::kVelocityWalk;
  state.progress = 0.25f;
  state.gait_type = GaitType::kTrotObstacle;
  state.foot_raise_height = 0.08f;
  state.position = {1.5f, -2.25f, 0.125f};
  state.body_height = 0.28f;
  state.velocity = {0.4f, -0.1f, 0.5f};
  state.yaw_speed = 0.5f;
  state.range_obstacle = {1.0f, 2.0f, 3.0f, 4.0f};
  return state;
}

class LibraryReadsState : public ::testing::TestWithParam<CrcRuleCase> {};

TEST_P(LibraryReadsState, OnlyWithItsCrcRule) {
  const CrcRuleCase& given = GetParam();
  UdpSocket robot(Endpoint{kLoopback, 0});
  sdk::UDP client(kLibraryHighLevel, 0, kLoopback, robot.local_endpoint().port);
  // The client's first command tells our "robot" where to answer.
  sdk::HighCmd hello{};
  client.InitCmdData(hello);
  client.SetSend(hello);
  ASSERT_EQ(client.Send(), static_cast<int>(kHighCmdLength));
  const std::optional<Datagram> command = robot.receive(kArrival);
  ASSERT_TRUE(command.has_value()) << "nothing arrived from the library";

  const HighState sent = distinct_state();
  const HighStateBytes packet = encode_high_state(sent, given.level_flag, given.form);
  const std::optional<std::string> send_error = robot.send_to(packet, to_sockaddr(command->from));
  ASSERT_FALSE(send_error.has_value()) << *send_error;
  const sdk::UDPState& counts = client.udpState;
  for (int attempt = 0; attempt < 100 && counts.RecvCount == 0 && counts.RecvCRCError == 0;
       ++attempt) {
    client.Recv();
    if (counts.RecvCount == 0 && counts.RecvCRCError == 0)
      std::this_thread::sleep_for(milliseconds(2));
  }
  EXPECT_EQ(counts.FlagError, 0u);
  if (!given.library_reads) {
    EXPECT_EQ(counts.RecvCRCError, 1u);
    EXPECT_EQ(counts.RecvCount, 0u);
    return;
  }
  EXPECT_EQ(counts.RecvCRCError, 0u);
  ASSERT_EQ(counts.RecvCount, 1u);
  sdk::HighState state{};
  client.GetRecv(state);
  EXPECT_EQ(byte_differences(packet, bytes_of(state)), "");
  const HighState read = from_library(state);
  EXPECT_EQ(read.imu_quaternion, sent.imu_quaternion);
  EXPECT_EQ(read.imu_gyroscope, sent.imu_gyroscope);
  EXPECT_EQ(read.imu_accelerometer, sent.imu_accelerometer);
  EXPECT_EQ(read.imu_rpy, sent.imu_rpy);
  EXPECT_EQ(read.imu_temperature, sent.imu_temperature);
  EXPECT_EQ(read.battery_percent, sent.battery_percent);
  EXPECT_EQ(read.foot_force, sent.foot_force);
  EXPECT_EQ(read.mode, sent.mode);
  EXPECT_EQ(read.progress, sent.progress);
  EXPECT_EQ(read.gait_type, sent.gait_type);
  EXPECT_EQ(read.foot_raise_height, sent.foot_raise_height);
  EXPECT_EQ(read.position, sent.position);
  EXPECT_EQ(read.body_height, sent.body_height);
  EXPECT_EQ(read.velocity, sent.velocity);
  EXPECT_EQ(read.yaw_speed, sent.yaw_speed);
  EXPECT_EQ(read.range_obstacle, sent.range_obstacle);
}

// The library (udp.cpp.o, UDP::Recv) checks a high-level packet's CRC (level flag 0xEE) in the
// encrypted form, as the robot stores it, and any other packet's in the plain form; a packet it
// refuses counts RecvCRCError and is not copied. (Its developer mode, off unless a program turns
// it on, also takes the plain form at 0xEE.)
INSTANTIATE_TEST_SUITE_P(
    CrcForms, LibraryReadsState,
    ::testing::Values(CrcRuleCase{"flag_ee_encrypted", kLevelFlagHighLevel, CrcForm::kEncrypted,
                                  true},
                      CrcRuleCase{"flag_ee_plain", kLevelFlagHighLevel, CrcForm::kPlain, false},
                      CrcRuleCase{"flag_00_plain", kLevelFlagZero, CrcForm::kPlain, true},
                      CrcRuleCase{"flag_00_encrypted", kLevelFlagZero, CrcForm::kEncrypted, false}),
    [](const ::testing::TestParamInfo<CrcRuleCase>& param_info) { return param_info.param.name; });

// --- 3. The library's client against our FakeGo1 -------------------------------------------------

TEST(LibraryClient, ReadsTheFakeGo1WithoutCrcErrorsAndSeesTheCommandedMotion) {
  constexpr float kForward = 0.4f;  // m/s
  constexpr float kYawRate = 0.5f;  // rad/s
  constexpr milliseconds kTick{2};  // example_walk.cpp's dt = 0.002 s
  constexpr milliseconds kWalk{400};
  constexpr milliseconds kStand{100};

  FakeGo1 robot;  // 127.0.0.1, any free port; answers every command with a HighState
  sdk::UDP client(kLibraryHighLevel, 0, kLoopback, robot.endpoint().port);

  std::optional<sdk::HighState> last_walking;  // the last state read while walking
  std::optional<sdk::HighState> last;
  const Clock::time_point start = Clock::now();
  Clock::time_point next = start;
  std::optional<Clock::time_point> stand_sent;
  for (Clock::time_point now = start; now < start + kWalk + kStand; now = Clock::now()) {
    const bool walk = now < start + kWalk;
    if (!walk && !stand_sent) stand_sent = now;
    // As example_walk.cpp writes it: comm.h's mode 2 (target velocity walking), gaitType 1
    // (trot); mode 0 (idle, default stand) at the end.
    sdk::HighCmd cmd{};
    client.InitCmdData(cmd);
    cmd.mode = walk ? 2 : 0;
    cmd.gaitType = walk ? 1 : 0;
    write_at(cmd, offsetof(sdk::HighCmd, velocity), std::array<float, 2>{walk ? kForward : 0.0f});
    cmd.yawSpeed = walk ? kYawRate : 0.0f;
    client.SetSend(cmd);
    client.Send();

    const unsigned long long read_before = client.udpState.RecvCount;
    client.Recv();
    if (client.udpState.RecvCount > read_before) {
      sdk::HighState state{};
      client.GetRecv(state);
      last = state;
      if (state.mode == 2) last_walking = state;
    }
    next += kTick;
    std::this_thread::sleep_until(next);
  }

  const sdk::UDPState& counts = client.udpState;
  EXPECT_EQ(counts.RecvCRCError, 0u) << "the library refused the fake's HighStates";
  // This build of the library never counts FlagError or SendError (only SendCount, RecvCount,
  // RecvCRCError and RecvLoseError, the Recv() calls that found nothing); checked all the same.
  EXPECT_EQ(counts.FlagError, 0u);
  EXPECT_EQ(counts.SendError, 0u);
  EXPECT_GE(counts.RecvCount, 20u) << "of " << counts.SendCount << " commands sent";
  const FakeGo1Counts fake = robot.counts();
  EXPECT_EQ(fake.refused, 0u) << "the fake refused the library's HighCmd: " << robot.last_refusal();
  ASSERT_TRUE(last_walking.has_value()) << "the library read no state while walking";
  ASSERT_TRUE(last.has_value());

  // While walking: the fake's velocity is the commanded one (forward, side, rotation).
  const HighState walking_state = from_library(*last_walking);
  EXPECT_EQ(walking_state.gait_type, GaitType::kTrot);
  EXPECT_EQ(walking_state.velocity, (std::array<float, 3>{kForward, 0.0f, kYawRate}));
  EXPECT_EQ(walking_state.yaw_speed, kYawRate);

  // Standing at the end: no velocity, and the pose the library read is the fake's own.
  const HighState final_state = from_library(*last);
  const Pose pose = robot.pose();
  EXPECT_EQ(final_state.mode, Mode::kIdle);
  EXPECT_EQ(final_state.velocity, (std::array<float, 3>{}));
  EXPECT_EQ(final_state.position,
            (std::array<float, 3>{static_cast<float>(pose.x), static_cast<float>(pose.y), 0.0f}));
  EXPECT_EQ(final_state.imu_rpy[2], static_cast<float>(pose.yaw));

  // And that pose is the commanded motion: an arc at kForward and kYawRate for as long as the fake
  // had the walking command in effect, which is about as long as we sent it.
  const std::vector<AppliedCommand> applied = robot.applied_commands();
  ASSERT_FALSE(applied.empty());
  ASSERT_EQ(applied.front().command.mode, Mode::kVelocityWalk);
  const auto first_stand = std::find_if(applied.begin(), applied.end(), [](const auto& entry) {
    return entry.command.mode == Mode::kIdle;
  });
  ASSERT_NE(first_stand, applied.end()) << "the fake never applied the stand command";
  const double walked = std::chrono::duration<double>(first_stand->at - applied.front().at).count();
  const double commanded = std::chrono::duration<double>(*stand_sent - start).count();
  EXPECT_NEAR(walked, commanded, 0.05);
  const double radius = kForward / kYawRate;
  EXPECT_NEAR(pose.yaw, kYawRate * walked, 1e-6);
  EXPECT_NEAR(pose.x, radius * std::sin(kYawRate * walked), 0.005);
  EXPECT_NEAR(pose.y, radius * (1.0 - std::cos(kYawRate * walked)), 0.005);
}

}  // namespace
}  // namespace oasis::hw::go1
