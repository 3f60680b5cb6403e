#pragma once
// What the link tests share: the sender on loopback at 200 Hz (5 ms ticks) and the timing
// their bounds are built from. "Halted within the watchdog timeout" allows kSchedulingMargin on
// top, for a late tick on a loaded 2-core machine (also under ASan).
#include <chrono>

#include "go1/endpoint.hpp"
#include "go1/sender.hpp"
#include "go1/watchdog.hpp"

namespace oasis::hw::go1::test {

using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;

constexpr milliseconds kWatchdogTimeout = kDefaultWatchdogTimeout;  // loopback_options keeps it
constexpr milliseconds kSchedulingMargin{50};
constexpr milliseconds kStopHold{100};

// A sender bound on loopback at 200 Hz that leaves process signals to the test, with the
// given holds of stop and of the final stand.
inline SenderOptions loopback_options(const Endpoint& robot, milliseconds stop_hold,
                                      milliseconds stand_hold) {
  SenderOptions options;
  options.robot = robot;
  options.local = Endpoint{"127.0.0.1", 0};
  options.rate_hz = 200.0;
  options.stop_hold = stop_hold;
  options.shutdown_stand_hold = stand_hold;
  options.obey_stop_signal = false;
  return options;
}

}  // namespace oasis::hw::go1::test
