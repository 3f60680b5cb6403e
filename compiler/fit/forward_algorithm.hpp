#pragma once
// The marginal likelihood of logged runs under the OAS filter's model, by the forward
// algorithm: the quantity the switching fit maximises over the switching matrix.
//
// Paper model (no observation model; Algorithm 1's assumptions, the observed state taken as
// true and the state sequence taken as given):
//   alpha_0(i) = prior(i)
//   predict    a'(i) = sum_j p(i | j) alpha_{t-1}(j)
//   evidence   c_t = sum_i a'(i) p(r_t | phi^i, o_t)
//   update     alpha_t(i) = a'(i) p(r_t | phi^i, o_t) / c_t
//   log L = sum_t log c_t = log p(r_1..r_T | o_1..o_T)
// Joint model (a state-observation model p(o | s); as the runtime's FilterMode::kJoint):
//   b_0(i, s) = prior(i) / S  (the state before the first logged step is unknown)
//   predict    b'(i, s') = sum_s P^i(s' | s, a_t) sum_j p(i | j) b_{t-1}(j, s)
//   evidence   c_t = sum_{i,s} b'(i, s) p(o_t | s) p(r_t | phi^i, x), x = s (reward follows
//              the true state) or o_t (it follows the observed state)
//   log L = sum_t log c_t = log p(o_1, r_1, ..., o_T, r_T | a_1..a_T)
// The detection model is the filter's soft one: p(r | phi^i, x) = 1 - epsilon when
// |r - R^i(x)| <= tolerance, else epsilon. With epsilon = 0 an unexplained step makes the
// likelihood 0 (log L = -infinity). An unknown action averages P^i over the actions enabled
// in s; a missing observation is a predict step without evidence.
//
// Cost of one evaluation: paper O(T N^2), joint O(T (N^2 S + N (S + E))) for T logged steps,
// N contexts, S states and E edges of one action.

#include <cstdint>
#include <vector>

#include "fit/switching_log.hpp"
#include "model/catalog_data.hpp"
#include "model/explicit_model.hpp"

namespace oasis::fit {

// Which state the received reward belongs to (the spec's `reward follows true|observed`).
enum class RewardFollows : std::uint32_t { kTrueState, kObservedState };

// p(observed state | true state).
struct StateNoise {
  enum class Kind : std::uint32_t { kNone, kSymmetric, kMatrix };
  Kind kind = Kind::kNone;
  double p_correct = 1.0;         // kSymmetric: P(o == s)
  std::vector<double> confusion;  // kMatrix: [S * S] row-major, row = true state
  RewardFollows reward = RewardFollows::kTrueState;
};

// What the likelihood needs of a compiled catalog.
struct FilterModel {
  std::uint32_t num_contexts = 0;
  std::uint32_t num_states = 0;
  std::uint32_t num_actions = 0;
  std::vector<double> prior;                // [N]
  std::vector<double> state_reward;         // [N * S] R^i(s) = block_reward[block_of[s]]
  std::vector<model::CsrData> transitions;  // [N] P^i over states (joint model only)
  StateNoise noise;
  double detection_epsilon = 0.001;
  double reward_tolerance = 1e-9;

  [[nodiscard]] bool joint() const { return noise.kind != StateNoise::Kind::kNone; }
};

// The prior and state rewards of `catalog`, the full-state transitions of `model`'s contexts.
FilterModel filter_model(const model::CatalogData& catalog, const model::ExplicitModel& model);

// log L of `runs` (each starting afresh from the prior) under the row-major N x N switching
// matrix `switching` (switching[i * N + j] = p(j | i)). -infinity when some step has
// likelihood 0.
double log_likelihood(const FilterModel& model, const std::vector<double>& switching,
                      const std::vector<LoggedRun>& runs);

// The symmetric switching matrix: p_stay on the diagonal, (1 - p_stay) / (N - 1) elsewhere.
std::vector<double> symmetric_switching(std::uint32_t num_contexts, double p_stay);

}  // namespace oasis::fit
