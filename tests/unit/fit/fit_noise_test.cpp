// The state-noise fit (compiler/fit/noise_fit.hpp): the closed-form MLE and its Wilson
// interval on simulated labels, a confusion matrix, and the Wilson interval itself.

#include <gtest/gtest.h>

#include "../../support/fit_simulation.hpp"
#include "fit/intervals.hpp"
#include "fit/noise_fit.hpp"
#include "fit/spec_fragment.hpp"

namespace oasis {
namespace {

TEST(FitNoise, WilsonIntervalKnownValues) {
  // 5 of 10: centre 0.5, half-width 1.96 / (1 + 0.384) * sqrt(0.025 + 0.0096) = 0.2634.
  const fit::Interval half = fit::wilson_interval(5, 10);
  EXPECT_NEAR(half.low, 0.2366, 1e-4);
  EXPECT_NEAR(half.high, 0.7634, 1e-4);
  // 0 of 10: [0, z^2 / (n + z^2)] = [0, 0.2775], not the Wald interval's single point.
  const fit::Interval none = fit::wilson_interval(0, 10);
  EXPECT_NEAR(none.low, 0.0, 1e-12);
  EXPECT_NEAR(none.high, 0.2775, 1e-4);
  const fit::Interval all = fit::wilson_interval(10, 10);
  EXPECT_NEAR(all.low, 0.7225, 1e-4);
  EXPECT_NEAR(all.high, 1.0, 1e-12);
}

TEST(FitNoise, RecoversTheSymmetricLevel) {
  // sigma = 0.2 over three states, 5000 pairs: the standard error is 0.0057; tolerance 0.02.
  const double sigma = 0.2;
  const std::vector<double> confusion{0.8, 0.1, 0.1, 0.1, 0.8, 0.1, 0.1, 0.1, 0.8};
  const fit::NoiseCounts counts = test::simulate_labels(confusion, 3, 5000, 3);
  const fit::SymmetricNoiseFit result = fit::fit_symmetric_noise(counts);
  EXPECT_EQ(result.total, 5000u);
  EXPECT_NEAR(result.sigma, sigma, 0.02);
  EXPECT_LE(result.interval.low, sigma);
  EXPECT_GE(result.interval.high, sigma);
  std::printf("symmetric noise: true 0.2000, fitted %.4f [%.4f, %.4f]\n", result.sigma,
              result.interval.low, result.interval.high);
}

TEST(FitNoise, RecoversAConfusionMatrix) {
  // About 2000 pairs per true state: each entry within 0.03 (3 standard errors or more).
  const std::vector<double> confusion{0.9, 0.1, 0.0, 0.05, 0.8, 0.15, 0.0, 0.3, 0.7};
  const fit::NoiseCounts counts = test::simulate_labels(confusion, 3, 6000, 5);
  const fit::ConfusionFit result = fit::fit_confusion(counts);
  ASSERT_EQ(result.matrix.size(), 9u);
  for (std::size_t k = 0; k < 9; ++k) {
    EXPECT_NEAR(result.matrix[k], confusion[k], 0.03) << "entry " << k;
    EXPECT_LE(result.intervals[k].low, result.matrix[k]);
    EXPECT_GE(result.intervals[k].high, result.matrix[k]);
  }
  // Never-seen confusions are 0 (the MLE) unless a pseudo-count is asked for.
  EXPECT_EQ(result.matrix[2], 0.0);
  EXPECT_GT(fit::fit_confusion(counts, 0.5).matrix[2], 0.0);
  EXPECT_TRUE(result.rows_without_pairs.empty());
  std::printf("confusion row s2: true (0.05 0.80 0.15), fitted (%.4f %.4f %.4f)\n",
              result.matrix[3], result.matrix[4], result.matrix[5]);
}

TEST(FitNoise, ARowWithoutPairsTakesTheSymmetricEstimate) {
  fit::NoiseCounts counts;
  counts.num_states = 3;
  counts.counts = {8, 1, 1, 1, 8, 1, 0, 0, 0};
  const fit::ConfusionFit result = fit::fit_confusion(counts);
  ASSERT_EQ(result.rows_without_pairs, std::vector<std::uint32_t>{2});
  EXPECT_NEAR(result.matrix[8], 0.8, 1e-12);
  EXPECT_NEAR(result.matrix[6], 0.1, 1e-12);
}

TEST(FitNoise, FragmentRowsSumToExactlyOne) {
  // 1/3 each rounds to 0.3333 three times: the largest entry takes up the rounding.
  const std::vector<std::string> row = fit::exact_row({1.0 / 3, 1.0 / 3, 1.0 / 3}, 4);
  EXPECT_EQ(row, (std::vector<std::string>{"0.3334", "0.3333", "0.3333"}));
  EXPECT_EQ(fit::state_noise_fragment(0.19704, "true"),
            "observation {\n  state noise 0.197;\n  reward follows true;\n}\n");
  EXPECT_EQ(fit::confusion_fragment({1.0, 0.0, 0.25, 0.75}, {"a", "b"}, "observed"),
            "observation {\n  state confusion {\n    a -> 1: a;\n    b -> 0.25: a + 0.75: b;\n"
            "  }\n  reward follows observed;\n}\n");
}

}  // namespace
}  // namespace oasis
