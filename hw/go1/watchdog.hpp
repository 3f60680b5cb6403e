#pragma once
// The fail-safe rule, as a pure function of time: while commands are fresh, pass them on; once
// none has been set for `timeout`, command stop (walking mode at zero velocity) for `stop_hold`,
// then stand (idle mode). Before the first command the robot is told to stand.

#include <chrono>
#include <optional>

namespace oasis::hw::go1 {

// How long the robot may go without a fresh command before it is stopped: the sender's default
// (SenderOptions::watchdog_timeout; robot.watchdog_ms in oasis-go1's settings). One control
// period of the Go1 treat spec (0.2 s), so the loops repeat their command between decisions.
inline constexpr std::chrono::milliseconds kDefaultWatchdogTimeout{200};

enum class SafetyAction { kPass, kStop, kStand };

class Watchdog {
 public:
  using Clock = std::chrono::steady_clock;

  Watchdog(Clock::duration timeout, Clock::duration stop_hold)
      : timeout_(timeout), stop_hold_(stop_hold) {}

  void feed(Clock::time_point now) { last_fed_ = now; }
  SafetyAction decide(Clock::time_point now) const;

 private:
  Clock::duration timeout_;
  Clock::duration stop_hold_;
  std::optional<Clock::time_point> last_fed_;
};

}  // namespace oasis::hw::go1
