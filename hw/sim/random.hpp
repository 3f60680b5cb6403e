// The simulator's random numbers: SplitMix64 and distributions written out here, so that a
// seed gives the same trial bit for bit on every standard library (std::normal_distribution
// and friends are not specified to the bit).
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>

namespace oasis::hw::sim {

class Random {
 public:
  explicit Random(std::uint64_t seed) : state_(seed) {}

  // A stream of its own for one concern (people, noise, schedule) of one trial: changing how
  // many numbers one concern draws does not shift the others.
  static Random stream(std::uint64_t seed, std::uint64_t concern) {
    Random mixer(seed ^ (0x9e3779b97f4a7c15ull * (concern + 1)));
    return Random(mixer.next());
  }

  std::uint64_t next() {  // SplitMix64 (Steele, Lea, Flood 2014)
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }

  // In [0, 1), 53 random bits.
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  double uniform(double low, double high) { return low + (high - low) * uniform(); }

  // An integer in [low, high], by rejection (no modulo bias).
  int integer(int low, int high) {
    const std::uint64_t span = static_cast<std::uint64_t>(high - low) + 1;
    const std::uint64_t limit = UINT64_MAX - UINT64_MAX % span;
    std::uint64_t draw = next();
    while (draw >= limit)
      draw = next();
    return low + static_cast<int>(draw % span);
  }

  bool chance(double probability) { return uniform() < probability; }

  // Box-Muller; one of the pair is kept for the next call.
  double normal(double mean = 0.0, double sigma = 1.0) {
    if (has_spare_) {
      has_spare_ = false;
      return mean + sigma * spare_;
    }
    const double u1 = 1.0 - uniform();  // (0, 1]: log is finite
    const double u2 = uniform();
    const double radius = std::sqrt(-2.0 * std::log(u1));
    spare_ = radius * std::sin(2.0 * std::numbers::pi * u2);
    has_spare_ = true;
    return mean + sigma * radius * std::cos(2.0 * std::numbers::pi * u2);
  }

  // Exponentially distributed with this mean: how long a behaviour lasts.
  double exponential(double mean) { return -mean * std::log(1.0 - uniform()); }

 private:
  std::uint64_t state_;
  double spare_ = 0.0;
  bool has_spare_ = false;
};

}  // namespace oasis::hw::sim
