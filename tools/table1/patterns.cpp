#include "table1/patterns.hpp"

namespace oasis::table1 {

std::string_view pattern_name(Pattern pattern) {
  switch (pattern) {
    case Pattern::kStep:
      return "step";
    case Pattern::kNoisyStep:
      return "noisy_step";
    case Pattern::kPeriodic:
      return "periodic";
    case Pattern::kNoisyPeriodic:
      return "noisy_periodic";
    case Pattern::kUniformRandom:
      return "uniform_random";
  }
  return "?";
}

std::optional<Pattern> parse_pattern(std::string_view name) {
  for (Pattern pattern : kAllPatterns)
    if (pattern_name(pattern) == name) return pattern;
  return std::nullopt;
}

bool pattern_is_noisy(Pattern pattern) {
  return pattern == Pattern::kNoisyStep || pattern == Pattern::kNoisyPeriodic;
}

std::vector<std::uint32_t> context_sequence(Pattern pattern, std::uint32_t steps,
                                            std::uint32_t num_contexts, SeededRandom& rng,
                                            const PatternOptions& options) {
  std::vector<std::uint32_t> sequence(steps, 0);
  for (std::uint32_t k = 0; k < steps; ++k) {
    switch (pattern) {
      case Pattern::kStep:
      case Pattern::kNoisyStep:
        sequence[k] = k < options.switch_at ? 0 : 1;
        break;
      case Pattern::kPeriodic:
      case Pattern::kNoisyPeriodic:
        sequence[k] = options.period == 0 ? 0 : (k / options.period) % 2;
        break;
      case Pattern::kUniformRandom:
        sequence[k] = rng.below(num_contexts);
        break;
    }
  }
  return sequence;
}

}  // namespace oasis::table1
