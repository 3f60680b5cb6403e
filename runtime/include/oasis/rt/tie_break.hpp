// oasis/rt/tie_break.hpp: how every filter of the runtime picks its maximum-likelihood
// abstraction when beliefs tie. One routine, so that AttentionFilter and HedgedFilter follow
// the same rule.
#pragma once

#include <cstdint>
#include <limits>

#include "oasis/rt/split_mix64.hpp"

namespace oasis::rt {

/// How the ML selection breaks ties. Two beliefs are tied when they differ by at most the
/// filter's tie tolerance (absolute).
enum class TieRule : std::uint32_t {
  /// Keep the current ML abstraction if it is among the tied; otherwise the lowest index.
  /// At construction there is no current abstraction, so the lowest tied index is taken.
  kKeep = 0,
  /// Pick uniformly among the tied with the filter's own PRNG (SplitMix64, seeded by
  /// FilterOptions::seed): the same seed gives the same choices on every platform. One PRNG
  /// draw (occasionally more, by rejection) per selection with two or more tied.
  kRandom = 1,
};

/// No current choice (before the first selection).
inline constexpr std::uint32_t kNoChoice = std::numeric_limits<std::uint32_t>::max();

/// argmax over values[0..n) (n >= 1), ties within `tolerance` of the largest broken by `rule`:
/// kKeep keeps `current` when it is tied (kNoChoice: none), else takes the lowest tied index;
/// kRandom draws uniformly among the tied from `random` (only when two or more are tied). O(n),
/// no allocation.
inline std::uint32_t select_with_ties(const double* values, std::uint32_t n, double tolerance,
                                      TieRule rule, std::uint32_t current,
                                      SplitMix64& random) noexcept {
  double best = values[0];
  for (std::uint32_t i = 1; i < n; ++i)
    if (values[i] > best) best = values[i];
  const double floor = best - tolerance;
  std::uint32_t tied = 0;
  std::uint32_t lowest = kNoChoice;
  bool current_tied = false;
  for (std::uint32_t i = 0; i < n; ++i) {
    if (values[i] < floor) continue;
    if (lowest == kNoChoice) lowest = i;
    if (i == current) current_tied = true;
    ++tied;
  }
  if (tied <= 1 || rule == TieRule::kKeep) return (tied > 1 && current_tied) ? current : lowest;
  std::uint64_t pick = random.uniform_below(tied);
  for (std::uint32_t i = 0; i < n; ++i) {
    if (values[i] < floor) continue;
    if (pick == 0) return i;
    --pick;
  }
  return lowest;  // not reached: pick < tied
}

}  // namespace oasis::rt
