#pragma once
// The simulator's random numbers: SplitMix64 (Steele, Lea, Flood 2014) with its own uniform
// helpers, so that a seed gives the same trial on every platform and standard library
// (std::uniform_int_distribution is not specified bit for bit).

#include <cstdint>

namespace oasis::sim {

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : state_(seed) {}

  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }

  // Uniform in [0, bound), bound >= 1, by rejection (no modulo bias).
  std::uint32_t below(std::uint32_t bound) {
    const std::uint64_t b = bound;
    const std::uint64_t threshold = (0 - b) % b;
    for (;;) {
      const std::uint64_t r = next();
      if (r >= threshold) return static_cast<std::uint32_t>(r % b);
    }
  }

  // Uniform in [0, 1) with 53 random bits.
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

  // True with probability p.
  bool bernoulli(double p) { return uniform() < p; }

 private:
  std::uint64_t state_;
};

// Combines a seed with a tag into an independent seed (the SplitMix64 finaliser of both).
inline std::uint64_t derive_seed(std::uint64_t seed, std::uint64_t tag) {
  Rng rng(seed ^ (tag * 0xD1B54A32D192ED03ull));
  return rng.next();
}

}  // namespace oasis::sim
