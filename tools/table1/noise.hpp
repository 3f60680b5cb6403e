#pragma once
// State noise with probability sigma, in three readings of the paper's "the observed state is
// another possible state rather than the true state":
//  * perceived: the robot sees a wrong state (uniformly among the others) and the reward it
//               perceives is the reward of the state it sees, under the true context;
//  * process:   the noise moves the true state to a uniformly random other state, which the
//               robot then sees exactly (and is rewarded for) - the trial continues from there;
//  * observed:  the robot sees a wrong state but receives the true state's reward.
// `none` sees the true state and its reward.

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "random/seeded_random.hpp"

namespace oasis::table1 {

enum class NoiseReading : std::uint32_t { kNone, kPerceived, kProcess, kObserved };

inline constexpr NoiseReading kNoisyReadings[] = {NoiseReading::kPerceived, NoiseReading::kProcess,
                                                  NoiseReading::kObserved};

std::string_view noise_name(NoiseReading reading);
std::optional<NoiseReading> parse_noise(std::string_view name);

// A state other than `state`, uniformly among the num_states - 1 others (num_states >= 2).
std::uint32_t other_state(std::uint32_t state, std::uint32_t num_states, SeededRandom& rng);

struct Sensed {
  std::uint32_t true_state = 0;      // after process noise
  std::uint32_t observed_state = 0;  // what the robot is told
  double reward = 0.0;               // what the robot is paid / perceives
};

// Applies `reading` with probability `sigma` to the true state `state`.
// `state_reward[s]` is R^{true context}(s). num_states = state_reward.size() (>= 2 if sigma > 0).
Sensed sense(NoiseReading reading, double sigma, std::uint32_t state,
             const std::vector<double>& state_reward, SeededRandom& rng);

}  // namespace oasis::table1
