#pragma once
// The exact mode's limits on its own work, reported as ExactLimitExceeded with a message that
// says what was passed and suggests the sound mode.

#include <cstddef>
#include <cstdint>
#include <string>

#include "modelcheck/engine.hpp"

namespace oasis::modelcheck {

// How many matrix entries (coefficients of the linear systems being eliminated, live and kept
// for back-substitution) one exact solve may hold at once. An entry costs about 80 bytes with
// its GMP limbs, so this is about 640 MB: the fill of an elimination order that goes wrong
// stops here with a clear message instead of exhausting memory.
inline constexpr std::size_t kMaxEliminationEntries = 8'000'000;

inline std::string suggest_sound_mode(const std::string& what) {
  return what + "; sound mode (--mode sound) computes a guaranteed interval instead";
}

// Throws when `value` has more bits than the limit allows.
inline void check_number_size(const Rational& value, std::size_t max_bits) {
  if (bit_size(value) > max_bits)
    throw ExactLimitExceeded(
        suggest_sound_mode("a computed value " + too_long_message(value, max_bits)));
}

inline void check_exact_state_count(std::uint64_t states, const Options& options) {
  if (states > options.max_exact_states)
    throw ExactLimitExceeded(suggest_sound_mode("the exact solve needs " + std::to_string(states) +
                                                " states, more than the limit of " +
                                                std::to_string(options.max_exact_states)));
}

}  // namespace oasis::modelcheck
