#pragma once
// The clock of a context's stages (StageSeconds in continuous_abstraction.hpp): each stage's
// seconds are read from the end of the one before.

#include <chrono>

namespace oasis::pipeline {

using StageClock = std::chrono::steady_clock;

// Seconds since `start`, and `start` moved to now for the next stage.
inline double seconds_since(StageClock::time_point& start) {
  const StageClock::time_point now = StageClock::now();
  const double seconds = std::chrono::duration<double>(now - start).count();
  start = now;
  return seconds;
}

}  // namespace oasis::pipeline
