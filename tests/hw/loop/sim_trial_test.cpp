// `oasis-go1 sim`'s trials: oasis-go1's loop on the hallway world, on both observation paths,
// with logs that the step-log reader and the Table II score take as they take a robot's.
#include "loop/sim_trial.hpp"

#include <filesystem>
#include <stdexcept>

#include <gtest/gtest.h>
#include <unistd.h>

#include "go1_treat_catalog.hpp"
#include "log/step_log_reader.hpp"
#include "log/step_log_writer.hpp"
#include "log/table2_metrics.hpp"
#include "loop/treat_contexts.hpp"
#include "spec_controller_settings.hpp"

namespace oasis::hw::loop {
namespace {

SimTrialSetup setup_for(sim::ObservationPath path, std::optional<std::uint64_t> steps = {}) {
  SimTrialSetup setup;
  setup.path = path;
  setup.controller = spec_settings(go1_treat::catalog());
  setup.max_steps = steps;
  return setup;
}

SimTrialResult trial(const std::string& controller, const SimTrialSetup& setup,
                     std::uint64_t seed = 5) {
  return run_sim_trial(go1_treat::catalog(), setup, settings::find_controller_profile(controller),
                       seed);
}

TEST(SimTrial, AFastTrialIsOneMinuteWithTruthOnEveryStep) {
  const SimTrialResult result = trial("ours", setup_for(sim::ObservationPath::kFast));
  ASSERT_EQ(result.records.size(), 300u);
  ASSERT_EQ(result.trace.size(), 300u);
  for (const log::StepRecord& record : result.records)
    ASSERT_TRUE(record.truth.has_value());
  EXPECT_DOUBLE_EQ(result.records.back().time_s, 59.8);
}

TEST(SimTrial, TheSameSeedGivesTheSameLog) {
  const SimTrialSetup setup = setup_for(sim::ObservationPath::kFast, 100);
  const SimTrialResult a = trial("paper", setup), b = trial("paper", setup);
  ASSERT_EQ(a.records.size(), b.records.size());
  for (std::size_t k = 0; k < a.records.size(); ++k) {
    EXPECT_EQ(a.records[k].state, b.records[k].state) << k;
    EXPECT_EQ(a.records[k].belief, b.records[k].belief) << k;
    EXPECT_EQ(a.records[k].action, b.records[k].action) << k;
  }
}

TEST(SimTrial, TheOracleIsAlwaysRightAndEarnsReward) {
  const SimTrialResult result = trial("oracle", setup_for(sim::ObservationPath::kFast));
  const log::TrialScore score = log::score_trial(result.records);
  EXPECT_EQ(score.accuracy, 1.0);
  EXPECT_EQ(score.max_lag_s, 0.0);
  EXPECT_GT(*score.normalized_reward, 0.2);
}

TEST(SimTrial, TheLogIsReadAndScoredLikeARobotsLog) {
  const SimTrialResult result = trial("ours", setup_for(sim::ObservationPath::kFast));
  const std::filesystem::path path = std::filesystem::temp_directory_path() /
                                     ("sim_trial_test_" + std::to_string(::getpid()) + ".jsonl");
  {
    log::StepLogWriter writer(path);
    for (const log::StepRecord& record : result.records)
      writer.write(record);
  }
  const log::StepLog read = log::read_step_log(path);
  std::filesystem::remove(path);
  ASSERT_EQ(read.records.size(), 300u);
  const log::TrialScore from_file = log::score_trial(read.records);
  const log::TrialScore direct = log::score_trial(result.records);
  EXPECT_TRUE(from_file.has_truth);
  EXPECT_EQ(from_file.reward_source, log::RewardSource::kTruth);
  EXPECT_EQ(from_file.accuracy, direct.accuracy);
  EXPECT_EQ(from_file.lags_s, direct.lags_s);
  EXPECT_EQ(from_file.normalized_reward, direct.normalized_reward);
  EXPECT_FALSE(from_file.lags_s.empty());  // every trial has at least one hand-off
}

TEST(SimTrial, AShortRenderedTrialRunsTheRealPerception) {
  const SimTrialResult result = trial("ours", setup_for(sim::ObservationPath::kRendered, 10));
  ASSERT_EQ(result.records.size(), 10u);
  int seen = 0;
  for (const log::StepRecord& record : result.records)
    seen += record.humans[0].seen + record.humans[1].seen;
  EXPECT_GT(seen, 0);  // the shirts were found in rendered pixels
}

TEST(SimTrial, ControllersAreTheShippedProfiles) {
  std::vector<std::string> names;
  for (const settings::ControllerProfile& profile : settings::shipped_controller_profiles())
    names.push_back(profile.name);
  EXPECT_EQ(names, (std::vector<std::string>{"oracle", "paper", "guard", "no-attention", "ours"}));
  EXPECT_THROW(settings::find_controller_profile("no-such"), std::invalid_argument);
}

}  // namespace
}  // namespace oasis::hw::loop
