// Table II from step logs: accuracy, hand-off lags in seconds and normalized reward on small
// hand-made logs whose answers are worked out in the comments, the no-truth case, the step
// period, the summary over trials and its text and JSON forms.

#include "log/table2_metrics.hpp"

#include <cmath>
#include <cstdint>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "log/table2_report.hpp"

namespace oasis::hw::log {
namespace {

// A log at `period` s a step: inferred[k] is the ML abstraction, truth[k] the true one (or no
// truth at all when `truth` is empty), observed[k] / true_reward[k] the rewards.
std::vector<StepRecord> make_log(const std::vector<std::uint32_t>& inferred,
                                 const std::vector<std::uint32_t>& truth,
                                 const std::vector<double>& observed,
                                 const std::vector<double>& true_reward, double period = 0.2) {
  std::vector<StepRecord> records(inferred.size());
  for (std::size_t k = 0; k < records.size(); ++k) {
    records[k].step = k;
    records[k].time_s = period * static_cast<double>(k);
    records[k].abstraction = inferred[k];
    records[k].reward = observed[k];
    if (!truth.empty()) records[k].truth = GroundTruth{truth[k], true_reward[k]};
  }
  return records;
}

TEST(Table2Trial, HandOffCaughtAfterTwoStepsIsAPointFourSecondLag) {
  //                k: 0  1  2  3  4  5
  const std::vector<std::uint32_t> truth{0, 0, 1, 1, 1, 1};
  const std::vector<std::uint32_t> ml{0, 0, 0, 0, 1, 1};
  // One hand-off at k = 2; the ML is right again at k = 4: 2 steps * 0.2 s = 0.4 s.
  // Right at k = 0, 1, 4, 5: accuracy 4 / 6. Rewards: truth sums to 1.2, observed to 0.6.
  const auto log =
      make_log(ml, truth, {0.1, 0.1, 0.1, 0.1, 0.1, 0.1}, {0.2, 0.2, 0.2, 0.2, 0.2, 0.2});
  const TrialScore score = score_trial(log);
  EXPECT_EQ(score.steps, 6u);
  EXPECT_NEAR(score.period_s, 0.2, 1e-12);
  EXPECT_TRUE(score.has_truth);
  ASSERT_TRUE(score.accuracy);
  EXPECT_DOUBLE_EQ(*score.accuracy, 4.0 / 6.0);
  ASSERT_EQ(score.lags_s.size(), 1u);
  EXPECT_NEAR(score.lags_s[0], 0.4, 1e-12);
  EXPECT_NEAR(*score.avg_lag_s, 0.4, 1e-12);
  EXPECT_NEAR(*score.max_lag_s, 0.4, 1e-12);
  EXPECT_EQ(score.reward_source, RewardSource::kTruth);
  EXPECT_NEAR(*score.normalized_reward, 1.2 / 6.0, 1e-12);
}

TEST(Table2Trial, SeveralHandOffsAverageAndMax) {
  //                k: 0  1  2  3  4  5  6  7  8  9
  const std::vector<std::uint32_t> truth{0, 0, 1, 1, 1, 0, 0, 0, 0, 1};
  const std::vector<std::uint32_t> ml{0, 0, 1, 1, 1, 1, 1, 1, 0, 0};
  // Hand-offs: k = 2 (right at once: 0 s), k = 5 (right at 8: 3 steps, 0.6 s), k = 9 (never
  // right in its 1-step segment: 1 step, 0.2 s). avg (0 + 0.6 + 0.2) / 3, max 0.6.
  // Wrong at 5, 6, 7, 9: accuracy 6 / 10.
  const std::vector<double> zeros(10, 0.0);
  const TrialScore score = score_trial(make_log(ml, truth, zeros, zeros));
  ASSERT_EQ(score.lags_s.size(), 3u);
  EXPECT_NEAR(score.lags_s[0], 0.0, 1e-12);
  EXPECT_NEAR(score.lags_s[1], 0.6, 1e-12);
  EXPECT_NEAR(score.lags_s[2], 0.2, 1e-12);
  EXPECT_NEAR(*score.avg_lag_s, 0.8 / 3.0, 1e-12);
  EXPECT_NEAR(*score.max_lag_s, 0.6, 1e-12);
  EXPECT_DOUBLE_EQ(*score.accuracy, 0.6);
}

TEST(Table2Trial, WithoutTruthAccuracyAndLagsAreUnavailableAndRewardIsObserved) {
  const auto log = make_log({0, 1, 1, 0}, {}, {1.0, 0.0, 0.5, 0.5}, {});
  const TrialScore score = score_trial(log);
  EXPECT_FALSE(score.has_truth);
  EXPECT_FALSE(score.accuracy);
  EXPECT_FALSE(score.avg_lag_s);
  EXPECT_FALSE(score.max_lag_s);
  EXPECT_TRUE(score.lags_s.empty());
  EXPECT_EQ(score.reward_source, RewardSource::kObserved);
  EXPECT_DOUBLE_EQ(*score.normalized_reward, 2.0 / 4.0);
}

TEST(Table2Trial, TruthOnSomeStepsOnlyCountsAsNoTruth) {
  auto log = make_log({0, 0, 1}, {0, 0, 1}, {0.0, 0.0, 0.3}, {1.0, 1.0, 1.0});
  log[1].truth.reset();
  const TrialScore score = score_trial(log);
  EXPECT_FALSE(score.accuracy);
  EXPECT_EQ(score.reward_source, RewardSource::kObserved);
  EXPECT_DOUBLE_EQ(*score.normalized_reward, 0.1);
}

TEST(Table2Trial, PeriodIsTheMedianStepUnlessGiven) {
  // Steps 0.2 s apart except one late frame (0.5 s): differences 0.2 0.5 0.2 0.2, median 0.2.
  auto log = make_log({0, 0, 0, 1, 1}, {0, 0, 1, 1, 1}, std::vector<double>(5, 0.0),
                      std::vector<double>(5, 0.0));
  const std::vector<double> times{0.0, 0.2, 0.7, 0.9, 1.1};
  for (std::size_t k = 0; k < log.size(); ++k)
    log[k].time_s = times[k];
  // Hand-off at k = 2, right at k = 3: 1 step.
  EXPECT_NEAR(*score_trial(log).avg_lag_s, 0.2, 1e-12);
  EXPECT_NEAR(*score_trial(log, ScoreOptions{0.25}).avg_lag_s, 0.25, 1e-12);
  // Four differences (an even count), 0.2 0.4 0.3 0.2: the mean of the middle two, 0.25.
  const std::vector<double> uneven{0.0, 0.2, 0.6, 0.9, 1.1};
  for (std::size_t k = 0; k < log.size(); ++k)
    log[k].time_s = uneven[k];
  EXPECT_NEAR(score_trial(log).period_s, 0.25, 1e-12);
}

TEST(Table2Trial, TimeThatDoesNotAdvanceIsRefused) {
  auto log = make_log({0, 0, 0}, {}, {0.0, 0.0, 0.0}, {}, 0.0);
  EXPECT_THROW((void)score_trial(log), std::invalid_argument);
  EXPECT_THROW((void)score_trial(log, ScoreOptions{-0.2}), std::invalid_argument);
  EXPECT_NO_THROW((void)score_trial(log, ScoreOptions{0.2}));
}

TEST(Table2Trial, EmptyAndSingleStepLogs) {
  const TrialScore empty = score_trial({});
  EXPECT_EQ(empty.steps, 0u);
  EXPECT_FALSE(empty.accuracy);
  EXPECT_FALSE(empty.normalized_reward);
  const TrialScore one = score_trial(make_log({1}, {1}, {0.0}, {0.4}));
  EXPECT_DOUBLE_EQ(*one.accuracy, 1.0);
  EXPECT_DOUBLE_EQ(*one.avg_lag_s, 0.0);
  EXPECT_DOUBLE_EQ(*one.normalized_reward, 0.4);
}

TrialScore trial(double accuracy, double avg_lag, double max_lag, double reward) {
  TrialScore score;
  score.steps = 10;
  score.has_truth = true;
  score.accuracy = accuracy;
  score.avg_lag_s = avg_lag;
  score.max_lag_s = max_lag;
  score.lags_s = {avg_lag};
  score.normalized_reward = reward;
  score.reward_source = RewardSource::kTruth;
  return score;
}

TEST(Table2Summary, MeanAndPopulationStdOverTrials) {
  // accuracy {0.8, 1.0}: mean 0.9, population std 0.1; avg lag {0.2, 0.6}: 0.4 ± 0.2;
  // max lag {0.4, 0.4}: 0.4 ± 0; reward {0.1, 0.3}: 0.2 ± 0.1.
  const Table2Summary summary =
      summarize_trials({trial(0.8, 0.2, 0.4, 0.1), trial(1.0, 0.6, 0.4, 0.3)});
  EXPECT_EQ(summary.trials, 2u);
  EXPECT_EQ(summary.steps, 20u);
  EXPECT_EQ(summary.handoffs, 2u);
  EXPECT_NEAR(summary.accuracy->mean, 0.9, 1e-12);
  EXPECT_NEAR(summary.accuracy->std, 0.1, 1e-12);
  EXPECT_NEAR(summary.avg_lag_s->mean, 0.4, 1e-12);
  EXPECT_NEAR(summary.avg_lag_s->std, 0.2, 1e-12);
  EXPECT_NEAR(summary.max_lag_s->std, 0.0, 1e-12);
  EXPECT_NEAR(summary.normalized_reward->mean, 0.2, 1e-12);
  EXPECT_NEAR(summary.normalized_reward->std, 0.1, 1e-12);
}

TEST(Table2Summary, AStatisticSomeTrialLacksIsUnavailable) {
  TrialScore camera_run;  // recorded on the robot: no truth
  camera_run.steps = 5;
  camera_run.normalized_reward = 0.5;
  const Table2Summary summary = summarize_trials({trial(0.8, 0.2, 0.4, 0.1), camera_run});
  EXPECT_FALSE(summary.accuracy);
  EXPECT_FALSE(summary.avg_lag_s);
  EXPECT_FALSE(summary.max_lag_s);
  ASSERT_TRUE(summary.normalized_reward);
  EXPECT_NEAR(summary.normalized_reward->mean, 0.3, 1e-12);
  EXPECT_EQ(summary.truth_trials, 1u);
  EXPECT_EQ(summary.truth_reward_trials, 1u);
}

TEST(Table2Report, PaperRowIsThePrintedOne) {
  EXPECT_EQ(kPaperTable2.trials, 12u);
  EXPECT_DOUBLE_EQ(kPaperTable2.accuracy.mean, 0.91);
  EXPECT_DOUBLE_EQ(kPaperTable2.accuracy.std, 0.07);
  EXPECT_DOUBLE_EQ(kPaperTable2.avg_lag_s.mean, 0.37);
  EXPECT_DOUBLE_EQ(kPaperTable2.max_lag_s.mean, 2.31);
  EXPECT_DOUBLE_EQ(kPaperTable2.normalized_reward.mean, 0.27);
  EXPECT_DOUBLE_EQ(kPaperTable2.normalized_reward.std, 0.11);
  EXPECT_DOUBLE_EQ(kPaperTable2.period_s, 0.2);
}

TEST(Table2Report, TextPutsOursBesideThePaper) {
  std::ostringstream out;
  print_table2(out, summarize_trials({trial(0.8, 0.2, 0.4, 0.1), trial(1.0, 0.6, 0.4, 0.3)}));
  const std::string text = out.str();
  EXPECT_NE(text.find("accuracy            | 0.90 ± 0.10   | 0.91 ± 0.07\n"), std::string::npos)
      << text;
  EXPECT_NE(text.find("average lag (s)     | 0.40 ± 0.20   | 0.37 ± 0.24\n"), std::string::npos);
  EXPECT_NE(text.find("max. lag (s)        | 0.40 ± 0.00   | 2.31 ± 1.48\n"), std::string::npos);
  EXPECT_NE(text.find("normalized reward   | 0.20 ± 0.10   | 0.27 ± 0.11\n"), std::string::npos);
  EXPECT_NE(text.find("hand-offs: 2; reward: truth"), std::string::npos);
}

TEST(Table2Report, TextSaysWhyAStatisticIsUnavailable) {
  TrialScore camera_run;
  camera_run.normalized_reward = 0.5;
  std::ostringstream out;
  print_table2(out, summarize_trials({camera_run}));
  const std::string text = out.str();
  EXPECT_NE(text.find("accuracy            | unavailable   | 0.91 ± 0.07\n"), std::string::npos)
      << text;
  EXPECT_NE(text.find("reward: observed"), std::string::npos);
  EXPECT_NE(text.find("need truth.abstraction on every step: 0 of 1 trials"), std::string::npos);
}

TEST(Table2Report, JsonHasMeanAndStdPerStatisticAndNullWhenUnavailable) {
  const nlohmann::ordered_json json =
      table2_json(summarize_trials({trial(0.8, 0.2, 0.4, 0.1), trial(1.0, 0.6, 0.4, 0.3)}));
  EXPECT_EQ(json["trials"], 2);
  EXPECT_EQ(json["reward_source"], "truth");
  for (const char* key : {"accuracy", "avg_lag_s", "max_lag_s", "normalized_reward"}) {
    ASSERT_TRUE(json[key].is_object()) << key;
    EXPECT_TRUE(json[key]["mean"].is_number()) << key;
    EXPECT_TRUE(json[key]["std"].is_number()) << key;
  }
  EXPECT_NEAR(json["avg_lag_s"]["mean"].get<double>(), 0.4, 1e-12);

  TrialScore camera_run;
  camera_run.normalized_reward = 0.5;
  const nlohmann::ordered_json partial = table2_json(summarize_trials({camera_run}));
  EXPECT_TRUE(partial["accuracy"].is_null());
  EXPECT_TRUE(partial["max_lag_s"].is_null());
  EXPECT_EQ(partial["reward_source"], "observed");
  EXPECT_DOUBLE_EQ(partial["normalized_reward"]["mean"].get<double>(), 0.5);
}

}  // namespace
}  // namespace oasis::hw::log
