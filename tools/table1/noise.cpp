#include "table1/noise.hpp"

namespace oasis::table1 {

std::string_view noise_name(NoiseReading reading) {
  switch (reading) {
    case NoiseReading::kNone:
      return "none";
    case NoiseReading::kPerceived:
      return "perceived";
    case NoiseReading::kProcess:
      return "process";
    case NoiseReading::kObserved:
      return "observed";
  }
  return "?";
}

std::optional<NoiseReading> parse_noise(std::string_view name) {
  for (NoiseReading reading : {NoiseReading::kNone, NoiseReading::kPerceived,
                               NoiseReading::kProcess, NoiseReading::kObserved})
    if (noise_name(reading) == name) return reading;
  return std::nullopt;
}

std::uint32_t other_state(std::uint32_t state, std::uint32_t num_states, SeededRandom& rng) {
  const std::uint32_t pick = rng.below(num_states - 1);
  return pick < state ? pick : pick + 1;
}

Sensed sense(NoiseReading reading, double sigma, std::uint32_t state,
             const std::vector<double>& state_reward, SeededRandom& rng) {
  const auto num_states = static_cast<std::uint32_t>(state_reward.size());
  Sensed sensed{state, state, state_reward[state]};
  if (reading == NoiseReading::kNone || num_states < 2 || !rng.chance(sigma)) return sensed;
  const std::uint32_t wrong = other_state(state, num_states, rng);
  switch (reading) {
    case NoiseReading::kNone:
      break;
    case NoiseReading::kPerceived:
      sensed.observed_state = wrong;
      sensed.reward = state_reward[wrong];
      break;
    case NoiseReading::kProcess:
      sensed.true_state = wrong;
      sensed.observed_state = wrong;
      sensed.reward = state_reward[wrong];
      break;
    case NoiseReading::kObserved:
      sensed.observed_state = wrong;
      break;
  }
  return sensed;
}

}  // namespace oasis::table1
