#pragma once
// The model checker's numeric engine: the values of PRISM's path and reward operators in every
// state of one transition matrix (a Markov chain, or an MDP optimised one way), exactly or with
// a sound interval, and the optimal scheduler where asked. The property language
// (compiler/property/) reduces every property to these calls: `G phi` is 1 - `F !phi` with the
// optimum turned around, a nested operator is a state set computed first.
//
// Semantics are PRISM's (and Storm's):
// * A state with no enabled action behaves as if it had a self-loop (PRISM adds one).
// * `until`: the probability of reaching `psi` along `phi` states. `bounded_until` within `k`
//   steps; `next` in one step.
// * Rewards: R(s, a) = state reward of s + the choice reward of (s, a) (model::RewardTable).
//   `reachability_reward` is the expected reward gathered before the first visit of `target`
//   (a target state earns nothing). It is infinite where the target is not reached with
//   probability 1: in a chain where P(F target) < 1; for kMin where no scheduler reaches it
//   surely (Pmax(F target) < 1); for kMax where some scheduler may miss it (Pmin < 1).
//   `cumulative_reward`: the expected reward of the first `k` steps (state rewards of steps
//   0..k-1 and the choice rewards of the first k choices). `instantaneous_reward`: the expected
//   state reward at step `k`.
//
// Two modes, stated in every result (Result::method):
// * kExact: rationals, by graph precomputation (Prob0/Prob1 and their MDP forms) and an exact
//   solve. Throws ExactLimitExceeded when the exact solve would pass Options::max_exact_states
//   or Options::max_number_bits, so that the caller can say so and suggest the sound mode.
// * kSound: for each state an interval [lower, upper] that contains the true value, with
//   upper - lower <= Options::precision in every state the result reports on; never a value
//   iteration stopped at a threshold (docs/properties.md says why each method is sound).

#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "model/explicit_model.hpp"
#include "support/limits.hpp"
#include "support/rational.hpp"

namespace oasis::modelcheck {

// One flag per state.
using StateSet = std::vector<bool>;

// How choices are resolved: kNone for a Markov chain (one action per state, or every action
// of a state taken as the same), kMin and kMax for the optimum over an MDP's schedulers.
enum class Optimum { kNone, kMin, kMax };

enum class Mode { kExact, kSound };

// The automatic choice of mode (`oasisc query --mode auto`, a catalog's stated properties):
// exact up to this many states, sound past it; and the exact solve gives up (for the sound
// one) once a number passes this many bits, since numbers that long mean slow rational
// arithmetic, and a model whose elimination grows them so far is answered sooner by interval
// iteration.
inline constexpr std::uint32_t kAutoExactStates = 100'000;
inline constexpr std::size_t kAutoExactNumberBits = std::size_t{1} << 16;

struct Options {
  Mode mode = Mode::kSound;
  double precision = 1e-6;      // kSound: the widest interval allowed
  bool want_scheduler = false;  // kMin and kMax only
  std::uint32_t max_exact_states = 1'000'000;
  std::size_t max_number_bits = limits::kDefaultMaxNumberBits;
  // Called now and then on long work with a short description ("interval iteration: 1200
  // sweeps, width 3e-4"); may be empty.
  std::function<void(const std::string&)> progress;
};

// A value in one state. Exactly one of `exact` (kExact) and [lower, upper] (kSound) is the
// answer; in kExact mode lower and upper both hold the nearest double of `exact`.
struct Value {
  bool infinite = false;  // rewards only: +infinity (then the other fields are unused)
  Rational exact;
  double lower = 0;
  double upper = 0;
};

// An optimal scheduler. Memoryless (unbounded properties): `action[s]` is the action taken in
// s, or kAnyAction where every action is optimal or the state does not matter (a target, a
// state of probability 0). Step-bounded properties: `by_step[i][s]` is the action at step i
// (i = 0 first), and `action` is empty.
struct Scheduler {
  static constexpr model::ActionIndex kAnyAction = UINT32_MAX;
  std::vector<model::ActionIndex> action;
  std::vector<std::vector<model::ActionIndex>> by_step;
};

struct Result {
  std::vector<Value> values;  // one per state
  std::optional<Scheduler> scheduler;
  // The method, for the output: "exact: Prob0/Prob1, then state elimination over GMP
  // rationals", "sound: interval iteration (Haddad and Monmege), outward rounding, 412 sweeps".
  std::string method;
};

// The exact solve was refused: too many states in one strongly connected part, or numbers
// past the limit. The message says which and suggests --mode sound.
class ExactLimitExceeded : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The matrix and its numbers, and how its choices are resolved.
struct Problem {
  const model::TransitionMatrix& matrix;
  const RationalPool& values;
  Optimum optimum = Optimum::kNone;
};

Result until(const Problem& problem, const StateSet& phi, const StateSet& psi,
             const Options& options);
Result bounded_until(const Problem& problem, const StateSet& phi, const StateSet& psi,
                     std::uint32_t steps, const Options& options);
Result next(const Problem& problem, const StateSet& psi, const Options& options);

Result reachability_reward(const Problem& problem, const model::RewardTable& rewards,
                           const StateSet& target, const Options& options);
Result cumulative_reward(const Problem& problem, const model::RewardTable& rewards,
                         std::uint32_t steps, const Options& options);
Result instantaneous_reward(const Problem& problem, const model::RewardTable& rewards,
                            std::uint32_t steps, const Options& options);

}  // namespace oasis::modelcheck
