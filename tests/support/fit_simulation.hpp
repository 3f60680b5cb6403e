#pragma once
// Seeded simulators whose parameters the fits (compiler/fit/) must recover.
//
// simulate_runs: the trial loop of oasis-sim's Table I (tools/table1/table1.cpp) with a Markov
// chain for the true context instead of a fixed pattern: the context keeps itself with
// p(stay) (or follows a full switching matrix), the robot picks an action uniformly among
// those enabled in the true state, the true state moves under the true context's P^c, and the
// sensor reports it through symmetric state noise sigma in one of two readings: `observed`
// (a wrong state is seen, the true state's reward received) or `perceived` (a wrong state is
// seen and its reward under the true context perceived).
// simulate_labels: (true, observed) pairs through a confusion matrix.
// simulate_depth: (true, measured) pairs with measured ~ Normal(d + bias, sigma(d)^2).

#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "fit/depth_noise_fit.hpp"
#include "fit/forward_algorithm.hpp"
#include "fit/noise_fit.hpp"
#include "fit/switching_log.hpp"
#include "oasis/rt/split_mix64.hpp"

namespace oasis::test {

// The runtime's SplitMix64 with the helpers these simulations use: the same draws everywhere.
class SplitMix {
 public:
  explicit SplitMix(std::uint64_t seed) : bits_(seed) {}
  std::uint64_t next() { return bits_.next(); }
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  std::uint32_t below(std::uint32_t bound) {
    return static_cast<std::uint32_t>(uniform() * bound) % bound;
  }
  // An index drawn from the distribution `p` (n entries).
  std::uint32_t pick(const double* p, std::uint32_t n) {
    double u = uniform();
    for (std::uint32_t k = 0; k + 1 < n; ++k) {
      u -= p[k];
      if (u < 0.0) return k;
    }
    return n - 1;
  }
  double normal() {  // Box-Muller
    const double u1 = 1.0 - uniform();
    const double u2 = uniform();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
  }

 private:
  rt::SplitMix64 bits_;
};

enum class SimulatedNoise { kNone, kObserved, kPerceived };

struct RunSimulation {
  std::vector<double> switching;  // N x N row-major
  SimulatedNoise noise = SimulatedNoise::kNone;
  double sigma = 0.0;
  std::uint32_t runs = 20;
  std::uint32_t steps = 500;
  std::uint64_t seed = 1;
  bool log_actions = true;  // false: every action unknown in the log
};

// Runs on the model of `filter` (its prior, state rewards and full-state transitions).
inline std::vector<fit::LoggedRun> simulate_runs(const fit::FilterModel& filter,
                                                 const RunSimulation& sim) {
  SplitMix rng(sim.seed);
  const std::uint32_t n = filter.num_contexts;
  const std::uint32_t states = filter.num_states;
  const std::uint32_t actions = filter.num_actions;
  std::vector<fit::LoggedRun> runs;
  for (std::uint32_t r = 0; r < sim.runs; ++r) {
    fit::LoggedRun run;
    run.name = "run" + std::to_string(r);
    std::uint32_t context = rng.pick(filter.prior.data(), n);
    std::uint32_t state = rng.below(states);
    for (std::uint32_t k = 0; k < sim.steps; ++k) {
      if (k > 0)
        context = rng.pick(sim.switching.data() + static_cast<std::size_t>(context) * n, n);
      const model::CsrData& csr = filter.transitions[context];
      std::vector<std::uint32_t> enabled;
      for (std::uint32_t a = 0; a < actions; ++a) {
        const std::size_t row = static_cast<std::size_t>(state) * actions + a;
        if (csr.choice_begin[row + 1] > csr.choice_begin[row]) enabled.push_back(a);
      }
      const std::uint32_t action = enabled[rng.below(static_cast<std::uint32_t>(enabled.size()))];
      const std::size_t row = static_cast<std::size_t>(state) * actions + action;
      const std::uint32_t begin = csr.choice_begin[row];
      const std::uint32_t count = csr.choice_begin[row + 1] - begin;
      state = csr.target[begin + rng.pick(csr.probability.data() + begin, count)];
      std::uint32_t observed = state;
      if (sim.noise != SimulatedNoise::kNone && rng.uniform() < sim.sigma) {
        const std::uint32_t other = rng.below(states - 1);
        observed = other < state ? other : other + 1;
      }
      const std::uint32_t rewarded = sim.noise == SimulatedNoise::kPerceived ? observed : state;
      fit::LoggedStep step;
      step.observed_state = observed;
      step.reward = filter.state_reward[static_cast<std::size_t>(context) * states + rewarded];
      step.action = sim.log_actions ? action : fit::kUnknownAction;
      run.steps.push_back(step);
    }
    runs.push_back(std::move(run));
  }
  return runs;
}

// `pairs` labelled observations of uniformly drawn true states through `confusion`.
inline fit::NoiseCounts simulate_labels(const std::vector<double>& confusion,
                                        std::uint32_t num_states, std::uint32_t pairs,
                                        std::uint64_t seed) {
  SplitMix rng(seed);
  fit::NoiseCounts counts;
  counts.num_states = num_states;
  counts.counts.assign(static_cast<std::size_t>(num_states) * num_states, 0);
  for (std::uint32_t k = 0; k < pairs; ++k) {
    const std::uint32_t s = rng.below(num_states);
    const std::uint32_t o =
        rng.pick(confusion.data() + static_cast<std::size_t>(s) * num_states, num_states);
    ++counts.counts[static_cast<std::size_t>(s) * num_states + o];
  }
  return counts;
}

// `per_distance` measurements at each distance of `distances`.
inline std::vector<fit::DepthPair> simulate_depth(const std::vector<double>& distances,
                                                  std::uint32_t per_distance, double bias, double a,
                                                  double b, double c, std::uint64_t seed) {
  SplitMix rng(seed);
  std::vector<fit::DepthPair> pairs;
  for (double d : distances)
    for (std::uint32_t k = 0; k < per_distance; ++k)
      pairs.push_back({d, d + bias + (a + b * d + c * d * d) * rng.normal()});
  return pairs;
}

}  // namespace oasis::test
