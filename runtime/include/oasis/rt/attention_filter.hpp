// oasis/rt/attention_filter.hpp: Online Attention Switching (Algorithm 1 of the paper).
//
// AttentionFilter keeps a belief over the catalog's abstractions, updates it from each
// observed (state, reward) pair, selects the maximum-likelihood (ML) abstraction phi^i and
// answers the action pi^i(z^i(s)) to apply next.
//
// Paper mode (the default) is Algorithm 1 exactly:
//   dynamics update     b'(i) = sum_j p(phi_t = i | phi_{t-1} = j) b(j)
//   measurement update  b(i)  = p(r_t | phi^i, s_t) b'(i) / sum_k p(r_t | phi^k, s_t) b'(k)
//   selection           i     = argmax_i b(i)          (ties: FilterOptions::tie_rule)
// with the deterministic detection model p(r | phi^i, s) = 1 if |r - R^i(s)| <= reward
// tolerance, else 0, where R^i(s) = block_reward[block_of[s]] of abstraction i.
//
// Options beyond the paper (all off by default, see FilterOptions): a zero-likelihood guard,
// a soft detection model, and two filters that know the sensor's noise: the joint filter over
// (abstraction, true state) on discrete catalogs, and the noise-aware filter on continuous ones.
// And one call beyond it: weigh_context(), a second measurement of the step from a sensor that sees
// the context itself now and then (the Go1's camera seeing the treat in someone's hand).
//
// No heap allocation after construction: the filter works in a caller-provided buffer of
// doubles (workspace_size() tells how many), which may be a std::vector allocated once, a
// static array or a FixedWorkspace<...>. The catalog view and the buffer must outlive the
// filter. The filter is not thread-safe; use one per thread.
//
// Cost of one step(): paper mode O(N^2) for N abstractions (the dense switching product) plus
// O(N) for the measurement; joint mode O(N^2 * S + N * (S + E_a)) where S is
// num_states and E_a the number of full-state edges of the action taken, i.e. one sparse
// matrix-vector product per abstraction plus the dense switching product per state.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

#include "oasis/rt/bsp_locator.hpp"
#include "oasis/rt/catalog_view.hpp"
#include "oasis/rt/grid_locator.hpp"
#include "oasis/rt/reward_mass.hpp"
#include "oasis/rt/split_mix64.hpp"
#include "oasis/rt/tie_break.hpp"

namespace oasis::rt {

/// Which filter runs.
enum class FilterMode : std::uint32_t {
  /// Algorithm 1 of the paper: a belief over abstractions, the observed state taken as true.
  /// Any catalog.
  kPaper = 0,
  /// The joint filter, discrete catalogs only: a belief over (abstraction i, true state s) that
  /// uses the catalog's observation model and full-state transitions (has_robust_section()).
  ///  predict:  b'(i, s') = sum_j p(i | j) sum_s P^i(s' | s, a_{t-1}) b(j, s)
  ///            (the context at time t governs the move s_{t-1} -> s_t; an (s, a) pair with
  ///            no successors in P^i loses its mass: the action could not have been taken
  ///            there);
  ///  weight:   b(i, s) ~ b'(i, s) * p(o_t | s) * p(r_t | phi^i, s)   (the reward depends on
  ///            the true state, so the detection model is applied at s, not at o_t; when the
  ///            catalog's observation model says the reward follows the observed state
  ///            (RewardSource::kObservedState) it is applied at o_t);
  ///  belief over abstractions: the marginal m(i) = sum_s b(i, s); ML over m;
  ///  abstract state for the policy: z = block_of^i(s*) with s* = argmax_s b(i, s) for the ML
  ///  abstraction i (ties: lowest state index).
  /// The first observation (start()) sets b(i, s) ~ prior(i) * p(o_0 | s).
  kJoint = 1,
  /// The noise-aware filter, continuous catalogs only: needs the catalog's position noise
  /// (PositionNoise) and runs Algorithm 1 with the noise-aware likelihood
  ///   p(r_t | phi^i, s_obs) = P(true state in a cell of phi^i whose reward matches r_t | s_obs)
  /// under the Gaussian sigma(d) of each variable (reward_mass.hpp: exact on grids, within a
  /// reported error on polytope cells), softened by detection_epsilon like the paper's model.
  /// A reading with a missed object (a non-finite relevant coordinate), or no reward observed
  /// (a non-finite reward: the robot could not see whether it was rewarded), skips the
  /// measurement update: the belief is the prediction alone (StepStatus::kMissingObservation).
  /// The policy is evaluated at the reading's block, as in Algorithm 1. It weighs each reading
  /// on its own and trusts the declared sigma(d); docs/RESULTS.md measures it when the camera's
  /// true noise differs.
  kNoiseAware = 2,
};

/// The mode that models the sensor's noise on `catalog`: kJoint on a discrete catalog,
/// kNoiseAware on a continuous one.
inline FilterMode noise_model_mode(const CatalogView& catalog) noexcept {
  return catalog.is_continuous() ? FilterMode::kNoiseAware : FilterMode::kJoint;
}

/// Options of AttentionFilter. The defaults give Algorithm 1 of the paper.
struct FilterOptions {
  FilterMode mode = FilterMode::kPaper;

  TieRule tie_rule = TieRule::kKeep;

  /// Seed of the PRNG used by TieRule::kRandom.
  std::uint64_t seed = 0;

  /// Absolute tolerance within which two beliefs count as tied for the ML selection.
  double tie_tolerance = 1e-12;

  /// Absolute tolerance of the detection model: the observed reward r matches abstraction i at
  /// state s when |r - R^i(s)| <= reward_tolerance. Rewards in a generated catalog are the
  /// spec's numbers rounded to double, and the robot reports the same numbers, so a tight
  /// tolerance suffices; widen it if rewards come through a noisy channel. A non-finite
  /// observed reward never matches.
  double reward_tolerance = 1e-9;

  /// Soft detection model: p(r | phi^i, s) = 1 - detection_epsilon on a match and
  /// detection_epsilon otherwise. 0 (the default) is the paper's deterministic model. Must be
  /// in [0, 1); with epsilon > 0 no likelihood is ever 0, so the guard below never fires.
  double detection_epsilon = 0.0;

  /// Zero-likelihood guard. When every abstraction (every (abstraction, state) pair in joint
  /// mode) has likelihood 0 the paper's normalisation divides 0 by 0: Algorithm 1 is
  /// undefined there. With the guard on, the filter keeps the predicted belief (the dynamics
  /// update alone). With it off (the default) the filter resets the belief to the prior (in
  /// joint mode: prior(i) * p(o_t | s), normalised, or prior(i) / S if that is 0 too): the
  /// observation contradicts every hypothesis, so it restarts from what it knew at t = 0.
  /// Either way step() reports StepStatus::kZeroLikelihood and the belief stays a
  /// distribution: the filter never produces a NaN.
  bool zero_likelihood_guard = false;

  /// Robust mode on a continuous catalog: when the reward-region integration stops refining
  /// (reward_mass.hpp).
  MassLimits mass_limits;
};

/// What step() did.
enum class StepStatus : std::uint32_t {
  kOk = 0,              ///< normal update
  kZeroLikelihood = 1,  ///< no hypothesis explained the observation; see zero_likelihood_guard
  kBadState = 2,        ///< observed_state >= num_states: input rejected, filter unchanged
  kBadAction = 3,       ///< action_taken >= num_actions: input rejected, filter unchanged
  kNotReady = 4,        ///< the filter could not be constructed (see error()); nothing done
  /// Noise-aware mode: the reading missed an object the abstractions attend to, so only
  /// the dynamics update ran (the belief is the prediction).
  kMissingObservation = 5,
};

/// The status's name in logs and bindings: "ok", "zero_likelihood", "bad_state", "bad_action",
/// "not_ready", "missing_observation".
inline const char* step_status_name(StepStatus status) {
  switch (status) {
    case StepStatus::kOk:
      return "ok";
    case StepStatus::kZeroLikelihood:
      return "zero_likelihood";
    case StepStatus::kBadState:
      return "bad_state";
    case StepStatus::kBadAction:
      return "bad_action";
    case StepStatus::kNotReady:
      return "not_ready";
    case StepStatus::kMissingObservation:
      return "missing_observation";
  }
  return "unknown";
}

/// Why construction failed.
enum class FilterError : std::uint32_t {
  kNone = 0,
  kWorkspaceTooSmall = 1,  ///< fewer doubles than workspace_size() asks for
  kNoRobustSection = 2,    ///< kJoint / kNoiseAware on a catalog without its noise model
  kBadOptions = 3,         ///< an option out of range (epsilon, tolerances)
  kEmptyCatalog = 4,       ///< num_abstractions, num_states or num_actions is 0
  kWrongCatalogKind = 5,   ///< kJoint on a continuous catalog, or kNoiseAware on a discrete one
};

/// Storage for a filter whose sizes are bounded at compile time: holds enough doubles for
/// MaxAbstractions abstractions of a discrete or continuous catalog (workspace_size()) and,
/// when MaxStates > 0, joint mode over MaxStates states.
template <std::size_t MaxAbstractions, std::size_t MaxStates = 0>
struct FixedWorkspace {
  static constexpr std::size_t kDoubles = 3 * MaxAbstractions > 2 * MaxAbstractions*(1 + MaxStates)
                                              ? 3 * MaxAbstractions
                                              : 2 * MaxAbstractions*(1 + MaxStates);
  std::array<double, kDoubles> data{};
  double* buffer() noexcept { return data.data(); }
  static constexpr std::size_t size() noexcept { return kDoubles; }
};

/// The OAS filter. See the top of this header for the algorithm and the cost per step.
class AttentionFilter {
 public:
  /// Number of doubles the workspace must hold for `catalog` under `options`:
  /// 2N in paper mode (3N on a continuous catalog), 2N + 2NS in joint mode (N abstractions,
  /// S states), 4N + RewardMass::workspace_size() in noise-aware mode.
  static std::size_t workspace_size(const CatalogView& catalog,
                                    const FilterOptions& options) noexcept {
    const std::size_t n = catalog.num_abstractions;
    if (catalog.is_continuous())  // and the block of the state in each
      return options.mode == FilterMode::kNoiseAware ? 4 * n + RewardMass::workspace_size(catalog)
                                                     : 3 * n;
    if (options.mode == FilterMode::kJoint)
      return 2 * n + 2 * n * static_cast<std::size_t>(catalog.num_states);
    return 2 * n;
  }

  /// Builds the filter and resets it (belief = prior, ML = argmax prior, no state yet).
  /// Requires: validate(catalog) is true (the filter does not re-check the catalog; it does
  /// check every sensor input). `workspace` points to `workspace_doubles` doubles that outlive
  /// the filter and are used by nothing else.
  /// Guarantees: ok() is true unless an error() condition holds, in which case every call
  /// below is a harmless no-op (step() returns kNotReady, action() kNoAction).
  AttentionFilter(const CatalogView& catalog, const FilterOptions& options, double* workspace,
                  std::size_t workspace_doubles) noexcept
      : catalog_(&catalog), options_(options) {
    if (catalog.num_abstractions == 0 || catalog.num_actions == 0 ||
        (catalog.num_states == 0 && !catalog.is_continuous())) {
      error_ = FilterError::kEmptyCatalog;
    } else if (!(options.detection_epsilon >= 0.0 && options.detection_epsilon < 1.0) ||
               !(options.reward_tolerance >= 0.0) || !(options.tie_tolerance >= 0.0) ||
               !(options.mass_limits.tolerance > 0.0 && options.mass_limits.tolerance < 1.0) ||
               options.mass_limits.max_boxes == 0) {
      error_ = FilterError::kBadOptions;
    } else if (options.mode != FilterMode::kPaper && options.mode != noise_model_mode(catalog)) {
      error_ = FilterError::kWrongCatalogKind;
    } else if (options.mode != FilterMode::kPaper && !catalog.has_noise_model()) {
      error_ = FilterError::kNoRobustSection;
    } else if (workspace == nullptr || workspace_doubles < workspace_size(catalog, options)) {
      error_ = FilterError::kWorkspaceTooSmall;
    }
    if (error_ != FilterError::kNone) return;
    const std::size_t n = catalog.num_abstractions;
    belief_ = workspace;
    scratch_ = workspace + n;
    if (catalog.is_continuous()) {
      located_ = workspace + 2 * n;
      if (options.mode == FilterMode::kNoiseAware) {
        likelihood_ = workspace + 3 * n;
        mass_ = RewardMass(catalog, options.mass_limits, workspace + 4 * n);
      }
    } else if (options.mode == FilterMode::kJoint) {
      joint_ = workspace + 2 * n;
      joint_scratch_ = joint_ + n * catalog.num_states;
    }
    reset();
  }

  /// Convenience: a FixedWorkspace as the buffer.
  template <std::size_t MaxAbstractions, std::size_t MaxStates>
  AttentionFilter(const CatalogView& catalog, const FilterOptions& options,
                  FixedWorkspace<MaxAbstractions, MaxStates>& workspace) noexcept
      : AttentionFilter(catalog, options, workspace.buffer(), workspace.size()) {}

  /// Not copyable: a copy would share the workspace with the original.
  AttentionFilter(const AttentionFilter&) = delete;
  AttentionFilter& operator=(const AttentionFilter&) = delete;

  bool ok() const noexcept { return error_ == FilterError::kNone; }
  FilterError error() const noexcept { return error_; }

  /// Back to t = 0: belief = prior, ML = argmax prior (tie rule applies; with kKeep the lowest
  /// tied index), PRNG reseeded, no observed state (action() is kNoAction until start() or
  /// step()). O(N) (paper) or O(N S) (joint).
  void reset() noexcept {
    if (!ok()) return;
    random_.reseed(options_.seed);
    reward_evidence_ = 1.0;
    mass_error_ = 0.0;
    has_state_ = false;
    state_ = 0;
    ml_ = kNoChoice;
    const std::uint32_t n = catalog_->num_abstractions;
    for (std::uint32_t i = 0; i < n; ++i)
      belief_[i] = catalog_->prior[i];
    if (joint_mode()) {
      const std::uint32_t states = catalog_->num_states;
      for (std::uint32_t i = 0; i < n; ++i)
        for (std::uint32_t s = 0; s < states; ++s)
          joint_[static_cast<std::size_t>(i) * states + s] = catalog_->prior[i] / states;
    }
    select_ml();
  }

  /// Records the initial observed state s_0 (Algorithm 1, line 1) so that action() can answer
  /// a_1 = pi^i(z^i(s_0)). Paper mode: the belief is unchanged (Algorithm 1 does not update on
  /// s_0). Robust mode: b(i, s) ~ prior(i) * p(o_0 | s). Returns kBadState (and changes
  /// nothing) if observed_state >= num_states. O(1) paper, O(N S) joint.
  StepStatus start(std::uint32_t observed_state) noexcept {
    if (!ok()) return StepStatus::kNotReady;
    if (observed_state >= catalog_->num_states) return StepStatus::kBadState;
    reset();
    state_ = observed_state;
    has_state_ = true;
    if (joint_mode()) {
      reset_joint_to_prior(observed_state);
      marginalise();
      select_ml();
    }
    return StepStatus::kOk;
  }

  /// One iteration of Algorithm 1's loop after the robot applied `action_taken` (a_t) and
  /// observed `observed_state` (s_t) and `observed_reward` (r_t).
  /// Requires nothing of the inputs: out-of-range indices are rejected (kBadState,
  /// kBadAction; the filter is unchanged), a NaN or infinite reward matches no abstraction.
  /// Guarantees: the belief stays a probability distribution (non-negative, sums to 1 up to
  /// rounding, no NaN); ml_abstraction() and action() are updated. In paper mode action_taken
  /// is only range-checked (the switching model does not depend on it). No allocation.
  StepStatus step(std::uint32_t observed_state, double observed_reward,
                  std::uint32_t action_taken) noexcept {
    if (!ok()) return StepStatus::kNotReady;
    if (observed_state >= catalog_->num_states) return StepStatus::kBadState;
    if (action_taken >= catalog_->num_actions) return StepStatus::kBadAction;
    const StepStatus status = joint_mode()
                                  ? joint_step(observed_state, observed_reward, action_taken)
                                  : paper_step(observed_state, observed_reward);
    state_ = observed_state;
    has_state_ = true;
    select_ml();
    return status;
  }

  /// Continuous catalogs: start() with the initial state vector (`size` doubles, at least
  /// state_dimension). Maps it to its block in every abstraction (rt::locate_partition_cell; a
  /// state outside an abstraction's domain is in its outside block). Returns kBadState on a
  /// discrete catalog or a short vector, changing nothing. O(N sum_i log cells_i) on grids, O(N
  /// depth d) on polytope cells.
  StepStatus start(const double* state, std::size_t size) noexcept {
    if (!ok()) return StepStatus::kNotReady;
    if (!catalog_->is_continuous() || state == nullptr || size < catalog_->state_dimension)
      return StepStatus::kBadState;
    reset();
    locate(state, size);
    has_state_ = true;
    return StepStatus::kOk;
  }

  /// Continuous catalogs: one iteration of Algorithm 1 with the observed state vector. The
  /// detection model compares the reward with block_reward of the state's block in each
  /// abstraction (kNoiseAware: the noise-aware likelihood, see FilterMode::kNoiseAware). Inputs
  /// are checked as by the discrete step(); a NaN coordinate puts the state outside
  /// (kNoiseAware: a missed observation). Cost O(N^2 + N sum_i log cells_i), plus in noise-aware
  /// mode one RewardMass::match_mass() per abstraction. No allocation.
  StepStatus step(const double* state, std::size_t size, double observed_reward,
                  std::uint32_t action_taken) noexcept {
    if (!ok()) return StepStatus::kNotReady;
    if (!catalog_->is_continuous() || state == nullptr || size < catalog_->state_dimension)
      return StepStatus::kBadState;
    if (action_taken >= catalog_->num_actions) return StepStatus::kBadAction;
    locate(state, size);
    const StepStatus status = noise_aware()
                                  ? noise_aware_update(state, observed_reward)
                                  : paper_update([&](std::uint32_t i) {
                                      return detection_at(i, located_block(i), observed_reward);
                                    });
    has_state_ = true;
    select_ml();
    return status;
  }

  /// A second measurement of the same time step, independent of the reward given the context:
  /// b(i) ~ likelihood[i] * b(i) (joint mode: every b(i, s) of row i),
  /// then the ML selection again. For a sensor that sees the context itself, now and then (the
  /// Go1's camera seeing the treat in someone's hand): call it after step() with p(what was
  /// seen | context i) per abstraction; call nothing when nothing was seen. `count` must be
  /// num_abstractions and every entry finite and >= 0 (else kBadState, belief unchanged). All
  /// zero, or zero wherever the belief is not, is kZeroLikelihood and the belief is kept.
  /// O(N) (O(N S) joint mode). No allocation.
  StepStatus weigh_context(const double* likelihood, std::size_t count) noexcept {
    if (!ok()) return StepStatus::kNotReady;
    const std::uint32_t n = catalog_->num_abstractions;
    if (likelihood == nullptr || count != n) return StepStatus::kBadState;
    double total = 0.0;
    for (std::uint32_t i = 0; i < n; ++i) {
      if (!(likelihood[i] >= 0.0) || !std::isfinite(likelihood[i])) return StepStatus::kBadState;
      total += likelihood[i] * belief_[i];
    }
    if (!(total > 0.0) || !std::isfinite(total)) return StepStatus::kZeroLikelihood;
    for (std::uint32_t i = 0; i < n; ++i)
      belief_[i] = likelihood[i] * belief_[i] / total;
    if (joint_mode()) {
      const std::uint32_t states = catalog_->num_states;
      for (std::uint32_t i = 0; i < n; ++i)
        for (std::uint32_t s = 0; s < states; ++s)
          joint_[static_cast<std::size_t>(i) * states + s] *= likelihood[i] / total;
    }
    select_ml();
    return StepStatus::kOk;
  }

  /// pi^i(z^i(s)) for the ML abstraction i and the current state s (the last observed state in
  /// paper mode; the most likely true state under i in joint mode). kNoAction before the
  /// first start()/step(), if construction failed, or if the block has no enabled action.
  /// O(1) in paper mode, O(S) in joint mode (finds the most likely state).
  std::uint32_t action() const noexcept {
    if (!ok() || !has_state_) return kNoAction;
    return catalog_->abstractions[ml_].policy[abstract_state()];
  }

  /// The ML abstraction index i (valid whenever ok()).
  std::uint32_t ml_abstraction() const noexcept { return ok() ? ml_ : 0; }

  /// The block z^i(s) the policy is evaluated at (see action()); 0 before any state.
  std::uint32_t abstract_state() const noexcept {
    if (!ok() || !has_state_) return 0;
    if (catalog_->is_continuous()) return located_block(ml_);
    return catalog_->abstractions[ml_].block_of[policy_state()];
  }

  /// The state the policy is evaluated at: the last observed state (paper mode) or the most
  /// likely true state under the ML abstraction (joint mode).
  std::uint32_t policy_state() const noexcept { return policy_state_under(ml_); }

  /// The same under abstraction i (< num_abstractions): the last observed state (paper mode)
  /// or argmax_s b(i, s) (joint mode; ties: lowest state). O(1) paper, O(S) joint.
  std::uint32_t policy_state_under(std::uint32_t i) const noexcept {
    if (!ok() || !has_state_) return 0;
    if (!joint_mode()) return state_;
    const std::uint32_t states = catalog_->num_states;
    const double* row = joint_ + static_cast<std::size_t>(i) * states;
    std::uint32_t best = 0;
    for (std::uint32_t s = 1; s < states; ++s)
      if (row[s] > row[best]) best = s;
    return best;
  }

  /// How well this filter's model predicted the last step's reward: p(r_t | observations up
  /// to t, rewards before t) (paper mode: sum_i p(r_t | phi^i, s_t) b'(i); joint mode: the same
  /// sum over (i, s) after weighting by p(o_t | s)). 0 when no hypothesis explained the reward
  /// (StepStatus::kZeroLikelihood); 1 after reset() and start(). Comparable between filters
  /// over the same observations: the hedged filter (hedged_filter.hpp) weighs models by it.
  double reward_evidence() const noexcept { return ok() ? reward_evidence_ : 0.0; }

  /// Noise-aware mode: the largest error bound of the last step's likelihoods
  /// (MassResult::error); 0 otherwise.
  double likelihood_error() const noexcept { return ok() ? mass_error_ : 0.0; }

  /// p(phi = i | history): the belief (the marginal in joint mode). i < num_abstractions.
  double belief(std::uint32_t i) const noexcept { return ok() ? belief_[i] : 0.0; }

  /// The whole belief, num_abstractions entries (null if construction failed).
  const double* beliefs() const noexcept { return ok() ? belief_ : nullptr; }

  /// Robust mode only: b(i, s), the joint belief (0 in paper mode).
  double joint_belief(std::uint32_t i, std::uint32_t s) const noexcept {
    if (!ok() || !joint_mode()) return 0.0;
    return joint_[static_cast<std::size_t>(i) * catalog_->num_states + s];
  }

  const FilterOptions& options() const noexcept { return options_; }
  const CatalogView& catalog() const noexcept { return *catalog_; }

 private:
  /// The joint filter over (abstraction, state) on a discrete catalog.
  bool joint_mode() const noexcept { return options_.mode == FilterMode::kJoint; }
  /// The noise-aware filter on a continuous catalog.
  bool noise_aware() const noexcept { return options_.mode == FilterMode::kNoiseAware; }

  /// p(r | phi^i, s) under the deterministic or soft detection model.
  double detection(std::uint32_t i, std::uint32_t s, double reward) const noexcept {
    return detection_at(i, catalog_->abstractions[i].block_of[s], reward);
  }

  /// The same for a state in block z of abstraction i.
  double detection_at(std::uint32_t i, std::uint32_t z, double reward) const noexcept {
    const double expected = catalog_->abstractions[i].block_reward[z];
    const bool match =
        std::isfinite(reward) && std::fabs(reward - expected) <= options_.reward_tolerance;
    return match ? 1.0 - options_.detection_epsilon : options_.detection_epsilon;
  }

  /// p(o | s) under the catalog's observation model (joint mode only).
  double observation(std::uint32_t observed, std::uint32_t s) const noexcept {
    const ObservationModel& obs = catalog_->observation;
    const std::uint32_t states = catalog_->num_states;
    if (obs.kind == ObservationKind::kMatrix)
      return obs.confusion[static_cast<std::size_t>(s) * states + observed];
    if (observed == s) return obs.p_correct;
    return (1.0 - obs.p_correct) / static_cast<double>(states - 1);
  }

  /// out(i) = sum_j p(i | j) in(j); switching is row-major p(j | i) = switching[i*N + j].
  void switch_predict(const double* in, double* out, std::size_t stride) const noexcept {
    const std::uint32_t n = catalog_->num_abstractions;
    for (std::uint32_t i = 0; i < n; ++i)
      out[i * stride] = 0.0;
    for (std::uint32_t j = 0; j < n; ++j) {
      const double mass = in[j * stride];
      if (mass == 0.0) continue;
      const double* row = catalog_->switching + static_cast<std::size_t>(j) * n;
      for (std::uint32_t i = 0; i < n; ++i)
        out[i * stride] += row[i] * mass;
    }
  }

  // Continuous catalogs: the block of the observed state in every abstraction, kept in the
  // workspace (block indices are below 2^32, exact in a double).
  void locate(const double* state, std::size_t size) noexcept {
    for (std::uint32_t i = 0; i < catalog_->num_abstractions; ++i) {
      const AbstractionView& abs = catalog_->abstractions[i];
      const std::uint32_t cell = locate_partition_cell(abs.grid, abs.bsp, state, size);
      located_[i] = cell == kOutsideCell ? abs.outside_block : abs.cell_block[cell];
    }
  }
  std::uint32_t located_block(std::uint32_t i) const noexcept {
    return static_cast<std::uint32_t>(located_[i]);
  }

  // Robust mode on a continuous catalog: Algorithm 1 with p(r | phi^i, s_obs) integrated
  // over the reading's Gaussian noise; the prediction alone when an object was missed.
  StepStatus noise_aware_update(const double* state, double reward) noexcept {
    const std::uint32_t n = catalog_->num_abstractions;
    if (!std::isfinite(reward)) return predict_only();
    if (catalog_->observation.reward_source == RewardSource::kObservedState)
      return paper_update(
          [&](std::uint32_t i) { return detection_at(i, located_block(i), reward); });
    mass_.measure(state);
    mass_error_ = 0.0;
    for (std::uint32_t i = 0; i < n; ++i) {
      const AbstractionView& abs = catalog_->abstractions[i];
      const MassResult mass = mass_.match_mass(abs, state, [&](std::uint32_t block) {
        return std::isfinite(reward) &&
               std::fabs(reward - abs.block_reward[block]) <= options_.reward_tolerance;
      });
      if (mass.missing) return predict_only();
      if (mass.error > mass_error_) mass_error_ = mass.error;
      const double eps = options_.detection_epsilon;
      likelihood_[i] = (1.0 - eps) * mass.probability + eps * (1.0 - mass.probability);
    }
    return paper_update([&](std::uint32_t i) { return likelihood_[i]; });
  }

  // The dynamics update alone: nothing was observed that the models could weigh.
  StepStatus predict_only() noexcept {
    switch_predict(belief_, scratch_, 1);
    for (std::uint32_t k = 0; k < catalog_->num_abstractions; ++k)
      belief_[k] = scratch_[k];
    reward_evidence_ = 1.0;
    mass_error_ = 0.0;
    return StepStatus::kMissingObservation;
  }

  StepStatus paper_step(std::uint32_t state, double reward) noexcept {
    return paper_update([&](std::uint32_t i) { return detection(i, state, reward); });
  }

  // Algorithm 1's update with the likelihood p(r_t | phi^i, s_t) given per abstraction.
  template <typename Likelihood>
  StepStatus paper_update(Likelihood&& likelihood) noexcept {
    const std::uint32_t n = catalog_->num_abstractions;
    switch_predict(belief_, scratch_, 1);  // scratch_ = predicted belief
    double total = 0.0;
    for (std::uint32_t i = 0; i < n; ++i) {
      const double weighted = likelihood(i) * scratch_[i];
      belief_[i] = weighted;
      total += weighted;
    }
    reward_evidence_ = total > 0.0 && std::isfinite(total) ? total : 0.0;
    if (total > 0.0 && std::isfinite(total)) {
      for (std::uint32_t i = 0; i < n; ++i)
        belief_[i] /= total;
      return StepStatus::kOk;
    }
    if (options_.zero_likelihood_guard) {
      for (std::uint32_t i = 0; i < n; ++i)
        belief_[i] = scratch_[i];
    } else {
      for (std::uint32_t i = 0; i < n; ++i)
        belief_[i] = catalog_->prior[i];
    }
    return StepStatus::kZeroLikelihood;
  }

  StepStatus joint_step(std::uint32_t observed, double reward, std::uint32_t action) noexcept {
    const std::uint32_t n = catalog_->num_abstractions;
    const std::uint32_t states = catalog_->num_states;
    const std::uint32_t actions = catalog_->num_actions;
    // 1. Switch: joint_scratch_(i, s) = sum_j p(i | j) joint_(j, s), one column per state.
    for (std::uint32_t s = 0; s < states; ++s)
      switch_predict(joint_ + s, joint_scratch_ + s, states);
    // 2. Move under P^i(. | s, a): joint_(i, s') = sum_s P^i(s' | s, a) joint_scratch_(i, s).
    for (std::uint32_t i = 0; i < n; ++i) {
      const TransitionsCsr& csr = catalog_->abstractions[i].state_transitions;
      const double* from = joint_scratch_ + static_cast<std::size_t>(i) * states;
      double* to = joint_ + static_cast<std::size_t>(i) * states;
      for (std::uint32_t s = 0; s < states; ++s)
        to[s] = 0.0;
      for (std::uint32_t s = 0; s < states; ++s) {
        const double mass = from[s];
        if (mass == 0.0) continue;
        const std::size_t row = static_cast<std::size_t>(s) * actions + action;
        for (std::uint32_t e = csr.choice_begin[row]; e < csr.choice_begin[row + 1]; ++e)
          to[csr.target[e]] += csr.probability[e] * mass;
      }
    }
    // Keep the prediction (normalised: mass may have been lost at disabled actions) in
    // joint_scratch_ for the guard.
    double predicted_total = 0.0;
    const std::size_t cells = static_cast<std::size_t>(n) * states;
    for (std::size_t k = 0; k < cells; ++k)
      predicted_total += joint_[k];
    // 3. Weight by p(o | s) and p(r | phi^i, s) (or p(r | phi^i, o) when the catalog says the
    // reward follows the observed state).
    const bool reward_follows_observed =
        catalog_->observation.reward_source == RewardSource::kObservedState;
    double total = 0.0;
    double observed_total = 0.0;  // p(o_t | past), up to the prediction's lost mass
    for (std::uint32_t i = 0; i < n; ++i) {
      double* row = joint_ + static_cast<std::size_t>(i) * states;
      double* kept = joint_scratch_ + static_cast<std::size_t>(i) * states;
      for (std::uint32_t s = 0; s < states; ++s) {
        kept[s] = row[s];
        if (row[s] == 0.0) continue;
        row[s] *= observation(observed, s);
        observed_total += row[s];
        row[s] *= detection(i, reward_follows_observed ? observed : s, reward);
        total += row[s];
      }
    }
    reward_evidence_ =
        observed_total > 0.0 && total > 0.0 && std::isfinite(total) ? total / observed_total : 0.0;
    StepStatus status = StepStatus::kOk;
    if (total > 0.0 && std::isfinite(total)) {
      for (std::size_t k = 0; k < cells; ++k)
        joint_[k] /= total;
    } else {
      status = StepStatus::kZeroLikelihood;
      if (options_.zero_likelihood_guard && predicted_total > 0.0 &&
          std::isfinite(predicted_total)) {
        for (std::size_t k = 0; k < cells; ++k)
          joint_[k] = joint_scratch_[k] / predicted_total;
      } else {
        reset_joint_to_prior(observed);
      }
    }
    marginalise();
    return status;
  }

  /// joint_(i, s) = prior(i) p(o | s) / sum_s p(o | s), or prior(i) / S if no state can
  /// produce the observation.
  void reset_joint_to_prior(std::uint32_t observed) noexcept {
    const std::uint32_t n = catalog_->num_abstractions;
    const std::uint32_t states = catalog_->num_states;
    double norm = 0.0;
    for (std::uint32_t s = 0; s < states; ++s)
      norm += observation(observed, s);
    for (std::uint32_t i = 0; i < n; ++i)
      for (std::uint32_t s = 0; s < states; ++s)
        joint_[static_cast<std::size_t>(i) * states + s] =
            norm > 0.0 ? catalog_->prior[i] * observation(observed, s) / norm
                       : catalog_->prior[i] / states;
  }

  void marginalise() noexcept {
    const std::uint32_t n = catalog_->num_abstractions;
    const std::uint32_t states = catalog_->num_states;
    for (std::uint32_t i = 0; i < n; ++i) {
      double sum = 0.0;
      const double* row = joint_ + static_cast<std::size_t>(i) * states;
      for (std::uint32_t s = 0; s < states; ++s)
        sum += row[s];
      belief_[i] = sum;
    }
  }

  /// i = argmax belief, ties per options_.tie_rule (tie_break.hpp). O(N).
  void select_ml() noexcept {
    ml_ = select_with_ties(belief_, catalog_->num_abstractions, options_.tie_tolerance,
                           options_.tie_rule, ml_, random_);
  }

  const CatalogView* catalog_ = nullptr;
  FilterOptions options_;
  FilterError error_ = FilterError::kNone;
  double* belief_ = nullptr;         // [N] current belief (marginal in joint mode)
  double* scratch_ = nullptr;        // [N] predicted belief (paper mode)
  double* joint_ = nullptr;          // [N*S] joint belief, row i = abstraction
  double* joint_scratch_ = nullptr;  // [N*S] joint mode scratch
  double* located_ = nullptr;        // [N] continuous catalogs: the state's block per abstraction
  double* likelihood_ = nullptr;     // [N] noise-aware mode: p(r_t | phi^i, s_obs)
  RewardMass mass_;                  // noise-aware mode: the likelihoods' integrator
  SplitMix64 random_;                // the random tie rule's draws
  double reward_evidence_ = 1.0;
  double mass_error_ = 0.0;
  std::uint32_t ml_ = kNoChoice;
  std::uint32_t state_ = 0;
  bool has_state_ = false;
};

}  // namespace oasis::rt
