// Seeded random draws for the simulators (oasis-sim's Table I, the hallway of oasis-go1 sim)
// and tests: the runtime's SplitMix64 (oasis/rt/split_mix64.hpp, the project's one generator)
// with the distributions written out here, so that a seed gives the same trial bit for bit on
// every platform and standard library (<random>'s distributions are not specified to the bit).
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>

#include "oasis/rt/split_mix64.hpp"

namespace oasis {

class SeededRandom {
 public:
  explicit SeededRandom(std::uint64_t seed) : bits_(seed) {}

  // A stream of its own for one concern (people, noise, schedule) of one trial: changing how
  // many numbers one concern draws does not shift the others.
  static SeededRandom stream(std::uint64_t seed, std::uint64_t concern) {
    SeededRandom mixer(seed ^ (0x9e3779b97f4a7c15ull * (concern + 1)));
    return SeededRandom(mixer.next());
  }

  std::uint64_t next() { return bits_.next(); }

  // In [0, 1), 53 random bits.
  double uniform() { return bits_.uniform(); }
  double uniform(double low, double high) { return low + (high - low) * uniform(); }

  // In [0, bound), bound >= 1, by rejection (no modulo bias).
  std::uint32_t below(std::uint32_t bound) {
    return static_cast<std::uint32_t>(bits_.uniform_below(bound));
  }

  // An integer in [low, high], by rejection (no modulo bias).
  int integer(int low, int high) {
    const std::uint64_t span = static_cast<std::uint64_t>(high - low) + 1;
    const std::uint64_t max = std::numeric_limits<std::uint64_t>::max();
    const std::uint64_t limit = max - max % span;
    std::uint64_t draw = next();
    while (draw >= limit)
      draw = next();
    return low + static_cast<int>(draw % span);
  }

  // True with this probability.
  bool chance(double probability) { return uniform() < probability; }

  // Box-Muller; one of the pair is kept for the next call.
  double normal(double mean = 0.0, double sigma = 1.0) {
    constexpr double kTwoPi = 6.283185307179586476925286766559;
    if (has_spare_) {
      has_spare_ = false;
      return mean + sigma * spare_;
    }
    const double u1 = 1.0 - uniform();  // (0, 1]: log is finite
    const double u2 = uniform();
    const double radius = std::sqrt(-2.0 * std::log(u1));
    spare_ = radius * std::sin(kTwoPi * u2);
    has_spare_ = true;
    return mean + sigma * radius * std::cos(kTwoPi * u2);
  }

  // Exponentially distributed with this mean: how long a behaviour lasts.
  double exponential(double mean) { return -mean * std::log(1.0 - uniform()); }

 private:
  rt::SplitMix64 bits_;
  double spare_ = 0.0;
  bool has_spare_ = false;
};

// Combines a seed with a tag into an independent seed (the SplitMix64 finaliser of both).
inline std::uint64_t derive_seed(std::uint64_t seed, std::uint64_t tag) {
  return SeededRandom(seed ^ (tag * 0xD1B54A32D192ED03ull)).next();
}

}  // namespace oasis
