#pragma once
// The statistics of the paper's Table II (the Go1 treat experiment), computed from step logs.
// The per-step definitions are oasis::metrics' (common/metrics/context_metrics.hpp), the same
// that score Table I; only the units and the sources differ:
//
//  * accuracy: fraction of steps whose ML abstraction (StepRecord::abstraction) equals
//    truth.abstraction. Only a log in which *every* step carries truth has one; otherwise it is
//    unavailable (nullopt), never guessed from the observed treat holder.
//  * hand-off: a switch of truth.abstraction. Its lag in seconds is metrics::switch_lags' lag
//    in steps times the step period: 0.2 s at the paper's 5 Hz. The period is given, or else
//    the median of the differences of successive time_s (robust to a late frame or two).
//    Average and max lag are over the trial's hand-offs (0 without any), unavailable with
//    accuracy.
//  * normalized reward: the cumulative reward divided by the number of steps ("the cumulative
//    reward averaged over the time horizon of a trial"). It uses truth.reward when every step
//    carries truth and the observed (perceived) reward otherwise; `reward_source` says which.
// Over several trials each statistic is mean ± population std (metrics::mean_std); a statistic
// that any trial lacks is unavailable for the summary rather than averaged over the others.

#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

#include "log/step_record.hpp"
#include "metrics/mean_std.hpp"

namespace oasis::hw::log {

enum class RewardSource { kTruth, kObserved };

std::string_view reward_source_name(RewardSource source);  // "truth" / "observed"

struct ScoreOptions {
  std::optional<double> period_s;  // the step period; nullopt: median of time_s differences
};

// One log (trial).
struct TrialScore {
  std::size_t steps = 0;
  double period_s = 0.0;   // as used; 0 for a log of fewer than two steps without a given period
  bool has_truth = false;  // every step carries truth
  std::optional<double> accuracy;
  std::vector<double> lags_s;  // one per hand-off, in order; empty without truth
  std::optional<double> avg_lag_s;
  std::optional<double> max_lag_s;
  std::optional<double> normalized_reward;  // nullopt for an empty log
  RewardSource reward_source = RewardSource::kObserved;
};

// Throws std::invalid_argument if the period (given or derived) is not finite and positive,
// i.e. time_s does not increase.
TrialScore score_trial(const std::vector<StepRecord>& records, const ScoreOptions& options = {});

// Several trials.
struct Table2Summary {
  std::size_t trials = 0;
  std::size_t steps = 0;                // over all trials
  std::size_t handoffs = 0;             // over the trials with truth
  std::size_t truth_trials = 0;         // trials whose every step carries truth
  std::size_t truth_reward_trials = 0;  // trials whose reward is truth.reward
  std::optional<metrics::MeanStd> accuracy;
  std::optional<metrics::MeanStd> avg_lag_s;
  std::optional<metrics::MeanStd> max_lag_s;
  std::optional<metrics::MeanStd> normalized_reward;
};

Table2Summary summarize_trials(const std::vector<TrialScore>& trials);

}  // namespace oasis::hw::log
