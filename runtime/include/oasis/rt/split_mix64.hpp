// oasis/rt/split_mix64.hpp: the project's one small PRNG.
//
// SplitMix64 (Steele, Lea and Flood, "Fast splittable pseudorandom number generators", 2014):
// 64 bits of state, a golden-ratio increment and a 64-bit finaliser. It is tiny, fast, passes
// BigCrush, and gives the same sequence on every platform and compiler, which is what the
// runtime's random tie rule and the simulators' seeded trials need. Not for cryptography.
#pragma once

#include <cstdint>

namespace oasis::rt {

class SplitMix64 {
 public:
  explicit SplitMix64(std::uint64_t seed = 0) noexcept : state_(seed) {}

  /// The next 64 random bits.
  std::uint64_t next() noexcept {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }

  /// Uniform in [0, bound) by rejection, without modulo bias. Requires bound >= 1. One draw,
  /// occasionally more.
  std::uint64_t uniform_below(std::uint64_t bound) noexcept {
    const std::uint64_t threshold = (0 - bound) % bound;  // 2^64 mod bound
    for (;;) {
      const std::uint64_t r = next();
      if (r >= threshold) return r % bound;
    }
  }

  /// Uniform in [0, 1), from the top 53 bits.
  double uniform() noexcept { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

  void reseed(std::uint64_t seed) noexcept { state_ = seed; }

 private:
  std::uint64_t state_;
};

}  // namespace oasis::rt
