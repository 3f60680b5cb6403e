#include "log/table2_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "metrics/context_metrics.hpp"

namespace oasis::hw::log {
namespace {

double median(std::vector<double> values) {
  const std::size_t middle = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + middle, values.end());
  const double upper = values[middle];
  if (values.size() % 2 == 1) return upper;
  const double lower = *std::max_element(values.begin(), values.begin() + middle);
  return (lower + upper) / 2.0;
}

double step_period(const std::vector<StepRecord>& records, const ScoreOptions& options) {
  double period = 0.0;
  if (options.period_s) {
    period = *options.period_s;
  } else if (records.size() >= 2) {
    std::vector<double> differences;
    for (std::size_t k = 1; k < records.size(); ++k)
      differences.push_back(records[k].time_s - records[k - 1].time_s);
    period = median(std::move(differences));
  } else {
    return 0.0;  // no two steps: no hand-off either, so no lag to convert
  }
  if (!std::isfinite(period) || period <= 0.0)
    throw std::invalid_argument("step period " + std::to_string(period) +
                                " s is not positive: give it, or log increasing time_s");
  return period;
}

bool every_step_has_truth(const std::vector<StepRecord>& records) {
  return !records.empty() && std::all_of(records.begin(), records.end(),
                                         [](const StepRecord& r) { return r.truth.has_value(); });
}

void score_contexts(const std::vector<StepRecord>& records, TrialScore& score) {
  std::vector<std::uint32_t> truth, inferred;
  for (const StepRecord& record : records) {
    truth.push_back(record.truth->abstraction);
    inferred.push_back(record.abstraction);
  }
  const metrics::TrialMetrics trial = metrics::trial_metrics(truth, inferred);
  score.accuracy = trial.accuracy;
  score.avg_lag_s = trial.avg_lag * score.period_s;
  score.max_lag_s = trial.max_lag * score.period_s;
  for (std::uint32_t lag : metrics::switch_lags(truth, inferred))
    score.lags_s.push_back(lag * score.period_s);
}

double normalized_reward(const std::vector<StepRecord>& records, RewardSource source) {
  double sum = 0.0;
  for (const StepRecord& record : records)
    sum += source == RewardSource::kTruth ? record.truth->reward : record.reward;
  return sum / static_cast<double>(records.size());
}

// mean ± std of `values` if every trial contributed one, else unavailable.
std::optional<metrics::MeanStd> summary_of(const std::vector<double>& values, std::size_t trials) {
  if (trials == 0 || values.size() != trials) return std::nullopt;
  return metrics::mean_std(values);
}

}  // namespace

std::string_view reward_source_name(RewardSource source) {
  return source == RewardSource::kTruth ? "truth" : "observed";
}

TrialScore score_trial(const std::vector<StepRecord>& records, const ScoreOptions& options) {
  TrialScore score;
  score.steps = records.size();
  score.period_s = step_period(records, options);
  score.has_truth = every_step_has_truth(records);
  if (score.has_truth) score_contexts(records, score);
  score.reward_source = score.has_truth ? RewardSource::kTruth : RewardSource::kObserved;
  if (!records.empty()) score.normalized_reward = normalized_reward(records, score.reward_source);
  return score;
}

Table2Summary summarize_trials(const std::vector<TrialScore>& trials) {
  Table2Summary summary;
  summary.trials = trials.size();
  std::vector<double> accuracy, avg_lag, max_lag, reward;
  for (const TrialScore& trial : trials) {
    summary.steps += trial.steps;
    summary.handoffs += trial.lags_s.size();
    summary.truth_trials += trial.has_truth ? 1 : 0;
    summary.truth_reward_trials += trial.reward_source == RewardSource::kTruth ? 1 : 0;
    if (trial.accuracy) accuracy.push_back(*trial.accuracy);
    if (trial.avg_lag_s) avg_lag.push_back(*trial.avg_lag_s);
    if (trial.max_lag_s) max_lag.push_back(*trial.max_lag_s);
    if (trial.normalized_reward) reward.push_back(*trial.normalized_reward);
  }
  summary.accuracy = summary_of(accuracy, trials.size());
  summary.avg_lag_s = summary_of(avg_lag, trials.size());
  summary.max_lag_s = summary_of(max_lag, trials.size());
  summary.normalized_reward = summary_of(reward, trials.size());
  return summary;
}

}  // namespace oasis::hw::log
