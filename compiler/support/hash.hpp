#pragma once
// Hashing of integers for the flat hash tables of exploration and refinement.

#include <cstdint>

namespace oasis {

// The splitmix64 finaliser: cheap, and spreads every input bit over the whole word, so that
// tables indexed by the low bits behave well on structured keys (state valuations, ids).
inline std::uint64_t mix_bits(std::uint64_t x) {
  x ^= x >> 30U;
  x *= 0xbf58476d1ce4e5b9ULL;
  x ^= x >> 27U;
  x *= 0x94d049bb133111ebULL;
  x ^= x >> 31U;
  return x;
}

}  // namespace oasis
