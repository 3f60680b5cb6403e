// The switching fit (compiler/fit/switching_fit.hpp) on runs simulated from the discrete
// tracking example: p_stay within 0.03 of the truth from 20 runs of 500 steps, without and
// with state noise; a full matrix within 0.04; the forward algorithm by hand on short runs.

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "../../support/fit_simulation.hpp"
#include "../../support/spec_models.hpp"
#include "fit/forward_algorithm.hpp"
#include "fit/switching_fit.hpp"
#include "pipeline/discrete_catalog.hpp"

namespace oasis {
namespace {

// specs/discrete_tracking.oasis without its observation block: the fits choose the model.
constexpr const char* kTracking = R"(
mdp discrete_tracking {
  states s1, s2, s3;
  actions L, R;
  init s2;
  s1, L -> s1;
  s2, L -> 1/2: s1 + 1/2: s2;
  s3, L -> 1/2: s1 + 1/2: s2;
  s1, R -> 1/2: s2 + 1/2: s3;
  s2, R -> 1/2: s2 + 1/2: s3;
  s3, R -> s3;
  discount 0.9;
}
catalog {
  context object_at_s3 { reward s3 : 1; }
  context object_at_s1 { reward s1 : 1; }
  switching stay 0.8;
  prior uniform;
}
)";

constexpr double kTolerance = 0.03;  // on p_stay, from 20 runs of 500 steps

fit::FilterModel tracking_filter() {
  const model::ExplicitModel model = test::explore_spec_text(kTracking);
  std::string error;
  const auto catalog = pipeline::build_catalog(model, 0, {}, error);
  EXPECT_TRUE(catalog) << error;
  return fit::filter_model(*catalog, model);
}

fit::SwitchingFit fit_or_fail(const fit::FilterModel& filter,
                              const std::vector<fit::LoggedRun>& runs, bool full = false) {
  fit::SwitchingFitOptions options;
  options.full = full;
  std::string error;
  const auto result = fit::fit_switching(filter, runs, options, error);
  EXPECT_TRUE(result) << error;
  return result ? *result : fit::SwitchingFit{};
}

test::RunSimulation symmetric_runs(double p_stay, std::uint64_t seed) {
  test::RunSimulation sim;
  sim.switching = fit::symmetric_switching(2, p_stay);
  sim.seed = seed;
  return sim;
}

TEST(FitSwitching, ForwardAlgorithmByHand) {
  fit::FilterModel filter = tracking_filter();
  filter.detection_epsilon = 0.1;
  // One step at s1 with reward 1: object_at_s1 explains it (0.9), object_at_s3 does not (0.1);
  // the prior is uniform, so p(r) = 0.5 * 0.1 + 0.5 * 0.9 = 0.5.
  fit::LoggedRun run{"by hand", {{0, 1.0, fit::kUnknownAction, 0}}};
  EXPECT_NEAR(fit::log_likelihood(filter, fit::symmetric_switching(2, 0.8), {run}), std::log(0.5),
              1e-12);
  // A second step at s3 with reward 1 (object_at_s3 now): alpha_1 = (0.1, 0.9); predicted
  // with p_stay 0.8: (0.08 + 0.18, 0.02 + 0.72) = (0.26, 0.74); p(r_2) = 0.26 * 0.9 + 0.74 * 0.1.
  run.steps.push_back({2, 1.0, fit::kUnknownAction, 0});
  EXPECT_NEAR(fit::log_likelihood(filter, fit::symmetric_switching(2, 0.8), {run}),
              std::log(0.5) + std::log(0.26 * 0.9 + 0.74 * 0.1), 1e-12);
  // A missing step before the second one: one more switch, (0.26, 0.74) -> (0.356, 0.644).
  run.steps[1].missing_before = 1;
  EXPECT_NEAR(fit::log_likelihood(filter, fit::symmetric_switching(2, 0.8), {run}),
              std::log(0.5) + std::log(0.356 * 0.9 + 0.644 * 0.1), 1e-12);
  // Without a soft detection an unexplained step has likelihood 0.
  filter.detection_epsilon = 0.0;
  run.steps.push_back({1, 5.0, fit::kUnknownAction, 0});
  EXPECT_EQ(fit::log_likelihood(filter, fit::symmetric_switching(2, 0.8), {run}),
            -std::numeric_limits<double>::infinity());
}

TEST(FitSwitching, JointForwardWithoutNoiseMatchesThePaperModelUpToTheStates) {
  // With p_correct = 1 the joint model also scores the observed moves; the contexts share
  // their transitions, so the difference is the same for every p_stay: both fits agree.
  const fit::FilterModel paper = tracking_filter();
  fit::FilterModel joint = paper;
  joint.noise.kind = fit::StateNoise::Kind::kSymmetric;
  joint.noise.p_correct = 1.0;
  const auto runs = test::simulate_runs(paper, symmetric_runs(0.8, 7));
  const double d1 = fit::log_likelihood(joint, fit::symmetric_switching(2, 0.6), runs) -
                    fit::log_likelihood(paper, fit::symmetric_switching(2, 0.6), runs);
  const double d2 = fit::log_likelihood(joint, fit::symmetric_switching(2, 0.9), runs) -
                    fit::log_likelihood(paper, fit::symmetric_switching(2, 0.9), runs);
  EXPECT_NEAR(d1, d2, 1e-6);
}

TEST(FitSwitching, RecoversPStayWithoutNoise) {
  const fit::FilterModel filter = tracking_filter();
  for (const double truth : {0.8, 0.5, 0.95}) {
    const auto runs = test::simulate_runs(filter, symmetric_runs(truth, 11));
    const fit::SwitchingFit result = fit_or_fail(filter, runs);
    EXPECT_NEAR(result.p_stay, truth, kTolerance) << "true p_stay " << truth;
    EXPECT_EQ(result.steps, 10000u);
    EXPECT_LE(result.p_stay_interval.low, result.p_stay);
    EXPECT_GE(result.p_stay_interval.high, result.p_stay);
    EXPECT_LT(result.p_stay_interval.high - result.p_stay_interval.low, 0.06);
    ASSERT_TRUE(result.p_stay_error);
    EXPECT_LT(*result.p_stay_error, 0.015);
    std::printf("no noise: true p_stay %.2f, fitted %.4f [%.4f, %.4f]\n", truth, result.p_stay,
                result.p_stay_interval.low, result.p_stay_interval.high);
  }
}

TEST(FitSwitching, RecoversPStayUnderObservedStateNoise) {
  // Table I's "observed" reading: a wrong state is seen, the true state's reward received;
  // the joint forward algorithm with the true noise level.
  fit::FilterModel filter = tracking_filter();
  for (const double sigma : {0.3, 0.7}) {
    test::RunSimulation sim = symmetric_runs(0.8, 23);
    sim.noise = test::SimulatedNoise::kObserved;
    sim.sigma = sigma;
    const auto runs = test::simulate_runs(filter, sim);
    filter.noise.kind = fit::StateNoise::Kind::kSymmetric;
    filter.noise.p_correct = 1.0 - sigma;
    filter.noise.reward = fit::RewardFollows::kTrueState;
    const fit::SwitchingFit result = fit_or_fail(filter, runs);
    EXPECT_NEAR(result.p_stay, 0.8, kTolerance) << "sigma " << sigma;
    std::printf("observed noise sigma %.1f: true p_stay 0.80, fitted %.4f [%.4f, %.4f]\n", sigma,
                result.p_stay, result.p_stay_interval.low, result.p_stay_interval.high);
  }
}

TEST(FitSwitching, RecoversPStayUnderPerceivedStateNoiseWithUnknownActions) {
  // The "perceived" reading (the reward is the observed state's) with the actions missing
  // from the log: the joint model with `reward follows observed` and random actions.
  fit::FilterModel filter = tracking_filter();
  test::RunSimulation sim = symmetric_runs(0.8, 29);
  sim.noise = test::SimulatedNoise::kPerceived;
  sim.sigma = 0.3;
  sim.log_actions = false;
  const auto runs = test::simulate_runs(filter, sim);
  filter.noise.kind = fit::StateNoise::Kind::kSymmetric;
  filter.noise.p_correct = 0.7;
  filter.noise.reward = fit::RewardFollows::kObservedState;
  const fit::SwitchingFit result = fit_or_fail(filter, runs);
  EXPECT_NEAR(result.p_stay, 0.8, kTolerance);
  // Algorithm 1's own model is exact for the rewards here (R^c of the observed state).
  const fit::SwitchingFit paper = fit_or_fail(tracking_filter(), runs);
  EXPECT_NEAR(paper.p_stay, 0.8, kTolerance);
  std::printf("perceived noise sigma 0.3: fitted joint %.4f, paper %.4f (true 0.80)\n",
              result.p_stay, paper.p_stay);
}

TEST(FitSwitching, RecoversAnAsymmetricMatrix) {
  const fit::FilterModel filter = tracking_filter();
  test::RunSimulation sim;
  sim.switching = {0.9, 0.1, 0.3, 0.7};
  sim.seed = 31;
  const auto runs = test::simulate_runs(filter, sim);
  const fit::SwitchingFit result = fit_or_fail(filter, runs, /*full=*/true);
  ASSERT_EQ(result.matrix.size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_NEAR(result.matrix[k], sim.switching[k], 0.04) << "entry " << k;
    ASSERT_TRUE(result.entry_intervals[k]) << "entry " << k;
    EXPECT_LE(result.entry_intervals[k]->low, result.matrix[k]);
    EXPECT_GE(result.entry_intervals[k]->high, result.matrix[k]);
  }
  EXPECT_NEAR(result.matrix[0] + result.matrix[1], 1.0, 1e-12);
  std::printf("full matrix: true (0.9 0.1; 0.3 0.7), fitted (%.4f %.4f; %.4f %.4f)\n",
              result.matrix[0], result.matrix[1], result.matrix[2], result.matrix[3]);
}

TEST(FitSwitching, RefusesWhatCannotBeFitted) {
  fit::FilterModel filter = tracking_filter();
  std::string error;
  EXPECT_FALSE(fit::fit_switching(filter, {}, {}, error));
  EXPECT_EQ(error, "the logs have no steps");
  // A reward no context gives, without a soft detection model.
  filter.detection_epsilon = 0.0;
  const std::vector<fit::LoggedRun> runs{{"bad", {{0, 7.0, fit::kUnknownAction, 0}}}};
  EXPECT_FALSE(fit::fit_switching(filter, runs, {}, error));
  EXPECT_NE(error.find("detection epsilon"), std::string::npos) << error;
}

}  // namespace
}  // namespace oasis
