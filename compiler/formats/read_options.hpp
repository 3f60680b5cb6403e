#pragma once
// Limits and leniency for reading explicit model files written by other tools.

#include <cstddef>
#include <cstdint>
#include <optional>

#include "support/limits.hpp"
#include "support/rational.hpp"

namespace oasis::formats {

struct ReadOptions {
  // Larger files are refused before they are read.
  std::size_t max_bytes = limits::kDefaultMaxInputBytes;
  // A file declaring more states is refused before anything is allocated for them.
  std::uint32_t max_states = limits::kDefaultMaxStates;
  // The memory the command may use (--memory-budget; per rank in oasisc-mpi), in bytes; 0:
  // none. A header declaring more than reading it could fit is refused before the body is
  // read (formats/model_size.hpp).
  std::uint64_t memory_budget = 0;
  // A number whose numerator or denominator has more bits is refused where it is written.
  std::size_t max_number_bits = limits::kDefaultMaxNumberBits;
  // PRISM files written with doubles rarely sum to exactly 1. When set, a choice whose
  // probabilities sum to within `tolerance` of 1 is accepted and its values are kept as
  // written (so the model is then only approximately stochastic). .aut files need no
  // tolerance: their last target takes the exact remainder.
  std::optional<Rational> tolerance;
};

}  // namespace oasis::formats
