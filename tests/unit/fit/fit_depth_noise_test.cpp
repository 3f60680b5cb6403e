// The depth-noise fit (compiler/fit/depth_noise_fit.hpp) on simulated calibration pairs
// with a known quadratic sigma(d) = a + b d + c d^2 and a constant bias, at the distances of
// a hallway calibration (0.5 m to 6 m, as in the paper's appendix figure).

#include <gtest/gtest.h>

#include "../../support/fit_simulation.hpp"
#include "fit/depth_noise_fit.hpp"

namespace oasis {
namespace {

constexpr double kBias = 0.02, kA = 0.01, kB = 0.004, kC = 0.003;

std::vector<double> hallway() {
  std::vector<double> distances;
  for (double d = 0.5; d <= 6.0 + 1e-9; d += 0.5)
    distances.push_back(d);
  return distances;
}

double true_sigma(double d) {
  return kA + kB * d + kC * d * d;
}

TEST(FitDepthNoise, RecoversAQuadraticSigma) {
  const auto pairs = test::simulate_depth(hallway(), 200, kBias, kA, kB, kC, 17);
  std::string error;
  const auto result = fit::fit_depth_noise(pairs, {}, error);
  ASSERT_TRUE(result) << error;
  ASSERT_EQ(result->sigma.size(), 3u);
  ASSERT_EQ(result->bias.size(), 1u);
  EXPECT_NEAR(result->bias[0], kBias, 0.003);
  // sigma(d) within 8% of the truth across the range, and inside its 95% interval.
  for (double d : {0.5, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0}) {
    EXPECT_NEAR(result->sigma_at(d), true_sigma(d), 0.08 * true_sigma(d)) << "d = " << d;
    const auto interval = result->sigma_interval(d);
    ASSERT_TRUE(interval);
    EXPECT_LE(interval->low, true_sigma(d)) << "d = " << d;
    EXPECT_GE(interval->high, true_sigma(d)) << "d = " << d;
  }
  // Every coefficient's interval holds the truth.
  ASSERT_EQ(result->intervals.size(), 4u);
  const double truth[] = {kBias, kA, kB, kC};
  for (std::size_t j = 0; j < 4; ++j) {
    EXPECT_LE(result->intervals[j].low, truth[j]) << "parameter " << j;
    EXPECT_GE(result->intervals[j].high, truth[j]) << "parameter " << j;
  }
  EXPECT_FALSE(result->floor_active);
  std::printf("depth noise: true b0 %.4f a %.4f b %.4f c %.4f; fitted %.4f %.4f %.4f %.4f\n", kBias,
              kA, kB, kC, result->bias[0], result->sigma[0], result->sigma[1], result->sigma[2]);
  for (double d : {1.0, 3.0, 5.0})
    std::printf("  sigma(%.0f m): true %.4f, fitted %.4f\n", d, true_sigma(d), result->sigma_at(d));
}

TEST(FitDepthNoise, OtherBiasAndDegreeChoices) {
  // No bias in the data: --bias none recovers sigma; a linear bias is recovered as such.
  const auto unbiased = test::simulate_depth(hallway(), 200, 0.0, kA, kB, kC, 19);
  std::string error;
  fit::DepthNoiseOptions none;
  none.bias = fit::DepthBias::kNone;
  const auto plain = fit::fit_depth_noise(unbiased, none, error);
  ASSERT_TRUE(plain) << error;
  EXPECT_TRUE(plain->bias.empty());
  EXPECT_NEAR(plain->sigma_at(3.0), true_sigma(3.0), 0.08 * true_sigma(3.0));

  std::vector<fit::DepthPair> scaled = unbiased;
  for (fit::DepthPair& pair : scaled)
    pair.measured += 0.01 * pair.true_distance;  // a 1% scale error
  fit::DepthNoiseOptions linear;
  linear.bias = fit::DepthBias::kLinear;
  const auto with_scale = fit::fit_depth_noise(scaled, linear, error);
  ASSERT_TRUE(with_scale) << error;
  EXPECT_NEAR(with_scale->bias[1], 0.01, 0.003);

  // A constant sigma from data with a constant sigma.
  const auto flat = test::simulate_depth(hallway(), 100, 0.0, 0.05, 0.0, 0.0, 23);
  fit::DepthNoiseOptions constant;
  constant.degree = 0;
  const auto level = fit::fit_depth_noise(flat, constant, error);
  ASSERT_TRUE(level) << error;
  ASSERT_EQ(level->sigma.size(), 1u);
  EXPECT_NEAR(level->sigma[0], 0.05, 0.003);
}

TEST(FitDepthNoise, RefusesUnidentifiableData) {
  std::string error;
  const auto two = test::simulate_depth({1.0, 2.0}, 50, 0.0, kA, kB, kC, 29);
  EXPECT_FALSE(fit::fit_depth_noise(two, {}, error));
  EXPECT_NE(error.find("3 or more distinct true distances"), std::string::npos) << error;
  const std::vector<fit::DepthPair> exact{{1.0, 1.0}, {2.0, 2.0}, {3.0, 3.0}, {4.0, 4.0}, {5, 5}};
  EXPECT_FALSE(fit::fit_depth_noise(exact, {}, error));
  EXPECT_NE(error.find("no spread"), std::string::npos) << error;
}

}  // namespace
}  // namespace oasis
