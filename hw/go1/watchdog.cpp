#include "go1/watchdog.hpp"

namespace oasis::hw::go1 {

SafetyAction Watchdog::decide(Clock::time_point now) const {
  if (!last_fed_) return SafetyAction::kStand;
  const Clock::duration silence = now - *last_fed_;
  if (silence < timeout_) return SafetyAction::kPass;
  if (silence < timeout_ + stop_hold_) return SafetyAction::kStop;
  return SafetyAction::kStand;
}

}  // namespace oasis::hw::go1
