#pragma once
// The true-context sequences of Table I: which context is in force at each step of a trial.
//
// Steps are indexed k = 0 .. steps-1 (k is the k-th call of the filter's step()).
//  * step:           context 0 for k < switch_at (100), context 1 from k = switch_at on;
//  * periodic:       context (k / period) % 2, period 10: switches at k = 10, 20, ...;
//  * uniform_random: a context drawn uniformly among all contexts at every step.
// The noisy_step and noisy_periodic patterns give the same sequences as step and periodic;
// they differ only in the state noise (noise.hpp) the trial applies.

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "random/seeded_random.hpp"

namespace oasis::table1 {

enum class Pattern : std::uint32_t { kStep, kNoisyStep, kPeriodic, kNoisyPeriodic, kUniformRandom };

inline constexpr Pattern kAllPatterns[] = {Pattern::kStep, Pattern::kNoisyStep, Pattern::kPeriodic,
                                           Pattern::kNoisyPeriodic, Pattern::kUniformRandom};

struct PatternOptions {
  std::uint32_t switch_at = 100;  // step pattern
  std::uint32_t period = 10;      // periodic pattern
};

std::string_view pattern_name(Pattern pattern);
std::optional<Pattern> parse_pattern(std::string_view name);

// True for the patterns that the paper runs with state noise (sigma).
bool pattern_is_noisy(Pattern pattern);

// The true context at each of `steps` steps, among `num_contexts` (>= 2 for step and periodic,
// which use contexts 0 and 1). `rng` is used by uniform_random only.
std::vector<std::uint32_t> context_sequence(Pattern pattern, std::uint32_t steps,
                                            std::uint32_t num_contexts, SeededRandom& rng,
                                            const PatternOptions& options = {});

}  // namespace oasis::table1
