#pragma once
// The command sender: its own thread sends one HighCmd per tick to the robot, built from the
// latest set_command() after clamping and ramping, and reads back HighState packets on the same
// socket (the robot answers the command's source address, FACTS §1 "Addresses").
//
// State is taken only from the robot: a datagram from any other address or port is dropped
// before it is decoded and counted (SenderStatus::datagrams_ignored). The CRC is no
// authentication, its rule is public, so without this any host on the robot's network could set
// the odometry the loop relies on. (Unitree's library connects its socket to the robot, and the
// kernel drops such datagrams; we compare instead, so that they can be counted and reported.)
//
// Fail safe (the watchdog rule, watchdog.hpp): when no set_command() came for
// `watchdog_timeout`, the sender commands stop (walking mode, zero velocity) for `stop_hold` and
// then stand (idle mode). stop(), the destructor and SIGINT/SIGTERM (once
// install_stop_signal_handlers() is called) run the shutdown sequence: stop for `stop_hold`
// (skipped if the robot was already told to stand), stand for `shutdown_stand_hold`, then the
// thread ends. Stop is zero at once, not ramped: the robot's own gait controller decelerates.

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <thread>

#include "go1/endpoint.hpp"
#include "go1/high_cmd.hpp"
#include "go1/high_state.hpp"
#include "go1/motion_limits.hpp"
#include "go1/protocol.hpp"
#include "go1/udp_socket.hpp"
#include "go1/watchdog.hpp"

namespace oasis::hw::go1 {

struct SenderOptions {
  Endpoint robot{kRobotAddress, kRobotPort};
  Endpoint local{"0.0.0.0", kDefaultLocalPort};
  std::uint8_t level_flag = kLevelFlagHighLevel;  // unconfirmed: 0x00 may be needed (README)
  std::optional<std::uint8_t> state_level_flag = kLevelFlagHighLevel;  // nullopt: accept any
  bool check_state_crc = true;
  // The SDK example sends every 2 ms and its comment allows 1-10 ms (FACTS §1 "Rate").
  double rate_hz = 500.0;
  std::chrono::milliseconds watchdog_timeout = kDefaultWatchdogTimeout;
  std::chrono::milliseconds stop_hold{300};
  std::chrono::milliseconds shutdown_stand_hold{100};
  MotionLimits limits;
  GaitType gait = GaitType::kTrot;
  bool obey_stop_signal = true;
};

enum class SenderPhase { kStanding, kDriving, kStopping, kShuttingDown, kFinished };

struct SenderStatus {
  SenderPhase phase = SenderPhase::kStanding;
  VelocityCommand commanded;  // after clamp and ramp, as last sent
  std::uint64_t packets_sent = 0;
  std::uint64_t send_failures = 0;
  std::string last_send_error;  // empty if none
  std::uint64_t states_received = 0;
  std::uint64_t states_refused = 0;
  std::string last_refusal;  // why the last refused HighState was refused
  std::optional<HighState> latest_state;
  std::uint64_t datagrams_ignored = 0;        // from anyone but the robot: never decoded
  std::optional<Endpoint> last_ignored_from;  // the source of the last of them
};

// "ignored 12 datagrams, the last from 192.168.12.40:5555 (not the robot)", or "" when none
// were: the one wording of the silence report, the end-of-run line and the tests.
std::string ignored_datagrams_text(std::uint64_t count, std::string_view last_from);
std::string ignored_datagrams_text(const SenderStatus& status);

class Sender {
 public:
  using Clock = std::chrono::steady_clock;

  // Throws LinkError for a bad address or a socket that cannot be bound, std::invalid_argument
  // for unusable options. The thread starts at once, commanding stand until set_command().
  explicit Sender(SenderOptions options);
  ~Sender();
  Sender(const Sender&) = delete;
  Sender& operator=(const Sender&) = delete;

  // Thread-safe. Ignored once the shutdown sequence began.
  void set_command(const VelocityCommand& wanted);

  // Runs the shutdown sequence (stop, then stand) and joins the thread. Idempotent.
  void stop();

  // True once the thread ended (after stop() or a stop signal) within `timeout`.
  bool wait_until_finished(std::chrono::milliseconds timeout);

  SenderStatus status() const;
  Endpoint local_endpoint() const { return socket_.local_endpoint(); }

 private:
  void run();
  bool shutdown_due(Clock::time_point now);
  HighCommand next_command(Clock::time_point now);
  HighCommand walk(const VelocityCommand& velocity) const;
  void send(const HighCommand& command);
  void read_states();

  const SenderOptions options_;
  const sockaddr_in robot_address_;
  // The robot as a received datagram's source reads (the canonical dotted quad), so that each
  // datagram is checked by one comparison, not by parsing its source again.
  const Endpoint robot_endpoint_;
  const Clock::duration tick_;
  UdpSocket socket_;

  mutable std::mutex mutex_;
  std::condition_variable finished_changed_;
  VelocityCommand target_;
  Watchdog watchdog_;
  bool stop_requested_ = false;
  std::optional<Clock::time_point> shutdown_started_;
  bool shutdown_skips_stop_ = false;
  SenderStatus status_;

  std::thread thread_;  // last: starts after everything above is constructed
};

}  // namespace oasis::hw::go1
