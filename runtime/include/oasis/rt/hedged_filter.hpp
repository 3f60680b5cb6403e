// oasis/rt/hedged_filter.hpp: a filter that is never much worse than Algorithm 1.
//
// The joint filter (FilterMode::kJoint) is right when the catalog's observation model
// is, and can be far worse than the paper's Algorithm 1 when it is not (Table I: 0.45 against
// 0.95 when the reward follows the observed state but the model says the true one). A robot
// cannot know which kind of noise it has, so HedgedFilter runs both and weighs them by how well
// each predicted the rewards seen so far - a posterior over the two models:
//
//   w_m  <-  w_m * e_m(t) / sum_k w_k * e_k(t)         e_m(t) = p(r_t | o_1..t, r_1..t-1, m)
//   w_m  <-  (1 - share) * w_m + share / 2             (fixed share: a model written off can
//                                                       come back when the noise changes)
//   B(i) =   w_paper * b_paper(i) + w_robust * b_robust(i),   ML over B (ties: the paper
//                                                       options' tie rule, tie_break.hpp)
//
// Both models condition on the same observed states, so their reward evidence is comparable
// (AttentionFilter::reward_evidence()). The action is the ML abstraction's policy at the state
// the heavier model believes in: the observed state (paper) or the most likely true state
// (robust). When every model gives the reward probability 0 the weights stay as they were.
//
// No heap allocation after construction: both filters work in one caller-provided buffer.
// Cost of one step: the sum of the two filters' costs plus O(N).
#pragma once

#include <cstddef>
#include <cstdint>

#include "oasis/rt/attention_filter.hpp"
#include "oasis/rt/catalog_view.hpp"
#include "oasis/rt/split_mix64.hpp"
#include "oasis/rt/tie_break.hpp"

namespace oasis::rt {

struct HedgeOptions {
  /// Algorithm 1 as the paper states it (the defaults), or with the usual options.
  FilterOptions paper;
  /// The model-based filter; its mode is forced to FilterMode::kJoint.
  FilterOptions robust;
  /// Prior weight of the robust model, in (0, 1).
  double robust_prior = 0.5;
  /// Fixed-share rate in [0, 1): after each step this fraction of the weight is spread evenly.
  double share = 0.01;
};

class HedgedFilter {
 public:
  /// Doubles the workspace must hold: both filters' workspaces and N for the mixed belief.
  static std::size_t workspace_size(const CatalogView& catalog,
                                    const HedgeOptions& options) noexcept {
    return AttentionFilter::workspace_size(catalog, options.paper) +
           AttentionFilter::workspace_size(catalog, robust_options(options)) +
           catalog.num_abstractions;
  }

  /// Requires validate(catalog). ok() is false when either filter fails to build (a catalog
  /// without an observation model: FilterError::kNoRobustSection), the workspace is too small
  /// or the hedge options are out of range (kBadOptions).
  HedgedFilter(const CatalogView& catalog, const HedgeOptions& options, double* workspace,
               std::size_t workspace_doubles) noexcept
      : catalog_(&catalog),
        options_(options),
        paper_(catalog, options.paper, workspace, paper_size(catalog, options, workspace_doubles)),
        robust_(catalog, robust_options(options),
                workspace + paper_size(catalog, options, workspace_doubles),
                robust_size(catalog, options, workspace_doubles)) {
    if (!(options.robust_prior > 0.0 && options.robust_prior < 1.0) ||
        !(options.share >= 0.0 && options.share < 1.0)) {
      error_ = FilterError::kBadOptions;
    } else if (workspace == nullptr || workspace_doubles < workspace_size(catalog, options)) {
      error_ = FilterError::kWorkspaceTooSmall;
    } else if (!paper_.ok()) {
      error_ = paper_.error();
    } else if (!robust_.ok()) {
      error_ = robust_.error();
    }
    if (error_ != FilterError::kNone) return;
    mixed_ = workspace + AttentionFilter::workspace_size(catalog, options.paper) +
             AttentionFilter::workspace_size(catalog, robust_options(options));
    reset();
  }

  HedgedFilter(const HedgedFilter&) = delete;
  HedgedFilter& operator=(const HedgedFilter&) = delete;

  bool ok() const noexcept { return error_ == FilterError::kNone; }
  FilterError error() const noexcept { return error_; }

  void reset() noexcept {
    if (!ok()) return;
    paper_.reset();
    robust_.reset();
    restart_mix();
  }

  /// As AttentionFilter::start().
  StepStatus start(std::uint32_t observed_state) noexcept {
    if (!ok()) return StepStatus::kNotReady;
    const StepStatus status = paper_.start(observed_state);
    if (status != StepStatus::kOk) return status;
    robust_.start(observed_state);
    restart_mix();
    return StepStatus::kOk;
  }

  /// As AttentionFilter::step(). kZeroLikelihood when neither model explained the reward.
  StepStatus step(std::uint32_t observed_state, double observed_reward,
                  std::uint32_t action_taken) noexcept {
    if (!ok()) return StepStatus::kNotReady;
    const StepStatus paper_status = paper_.step(observed_state, observed_reward, action_taken);
    if (paper_status == StepStatus::kBadState || paper_status == StepStatus::kBadAction)
      return paper_status;
    const StepStatus robust_status = robust_.step(observed_state, observed_reward, action_taken);
    const double paper_mass = (1.0 - robust_weight_) * paper_.reward_evidence();
    const double robust_mass = robust_weight_ * robust_.reward_evidence();
    const double total = paper_mass + robust_mass;
    if (total > 0.0) robust_weight_ = robust_mass / total;
    robust_weight_ = (1.0 - options_.share) * robust_weight_ + options_.share / 2.0;
    mix();
    const bool neither =
        paper_status == StepStatus::kZeroLikelihood && robust_status == StepStatus::kZeroLikelihood;
    return neither ? StepStatus::kZeroLikelihood : StepStatus::kOk;
  }

  /// The ML abstraction's policy at the state the heavier model believes in.
  std::uint32_t action() const noexcept {
    if (!ok()) return kNoAction;
    const AttentionFilter& lead = robust_weight_ > 0.5 ? robust_ : paper_;
    if (lead.action() == kNoAction) return kNoAction;  // no state yet
    const AbstractionView& abstraction = catalog_->abstractions[ml_];
    return abstraction.policy[abstraction.block_of[lead.policy_state_under(ml_)]];
  }

  std::uint32_t ml_abstraction() const noexcept { return ok() ? ml_ : 0; }
  double belief(std::uint32_t i) const noexcept { return ok() ? mixed_[i] : 0.0; }
  const double* beliefs() const noexcept { return ok() ? mixed_ : nullptr; }
  /// The posterior weight of the robust (declared-model) filter; the paper's is 1 minus it.
  double robust_weight() const noexcept { return ok() ? robust_weight_ : 0.0; }
  const AttentionFilter& paper_filter() const noexcept { return paper_; }
  const AttentionFilter& robust_filter() const noexcept { return robust_; }

 private:
  static FilterOptions robust_options(const HedgeOptions& options) noexcept {
    FilterOptions robust = options.robust;
    robust.mode = FilterMode::kJoint;
    return robust;
  }
  // The two filters' shares of the buffer; 0 when it is too small (each then fails on its own).
  static std::size_t paper_size(const CatalogView& catalog, const HedgeOptions& options,
                                std::size_t available) noexcept {
    const std::size_t wanted = AttentionFilter::workspace_size(catalog, options.paper);
    return available >= wanted ? wanted : 0;
  }
  static std::size_t robust_size(const CatalogView& catalog, const HedgeOptions& options,
                                 std::size_t available) noexcept {
    const std::size_t before = paper_size(catalog, options, available);
    const std::size_t wanted = AttentionFilter::workspace_size(catalog, robust_options(options));
    return before > 0 && available - before >= wanted ? wanted : 0;
  }

  // Back to t = 0 for the mixing: the prior weight, the tie rule's PRNG reseeded, no choice.
  void restart_mix() noexcept {
    robust_weight_ = options_.robust_prior;
    random_.reseed(options_.paper.seed);
    ml_ = kNoChoice;
    mix();
  }

  // The mixed belief and its ML abstraction, ties broken by the paper options' tie rule and
  // tolerance through the runtime's one routine (kKeep keeps this filter's own last choice).
  void mix() noexcept {
    const std::uint32_t n = catalog_->num_abstractions;
    for (std::uint32_t i = 0; i < n; ++i)
      mixed_[i] = (1.0 - robust_weight_) * paper_.belief(i) + robust_weight_ * robust_.belief(i);
    ml_ = select_with_ties(mixed_, n, options_.paper.tie_tolerance, options_.paper.tie_rule, ml_,
                           random_);
  }

  const CatalogView* catalog_;
  HedgeOptions options_;
  AttentionFilter paper_;
  AttentionFilter robust_;
  FilterError error_ = FilterError::kNone;
  double* mixed_ = nullptr;
  double robust_weight_ = 0.5;
  SplitMix64 random_;  // the random tie rule's draws, seeded by the paper options' seed
  std::uint32_t ml_ = kNoChoice;
};

}  // namespace oasis::rt
