// The noise-aware likelihood of continuous catalogs (runtime, C++17 only): the Gaussian mass
// of an abstraction's reward cells against closed forms (box regions: products of normal
// CDFs; a half-plane: one normal CDF of a sum), on grids and on polytope cells (BSP), within
// the reported error bound; sigma 0 reduces to Algorithm 1's detection; a missed object; and
// the filter's robust mode on a continuous catalog.

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "oasis/rt/attention_filter.hpp"
#include "oasis/rt/catalog_validation.hpp"
#include "oasis/rt/catalog_view.hpp"
#include "oasis/rt/reward_mass.hpp"

namespace {

namespace rt = oasis::rt;

double phi(double z) {
  return 0.5 * std::erfc(-z / std::sqrt(2.0));
}

// A continuous catalog over (x, y) with one object measuring both. Abstraction k rewards the
// box x in [k + 1, k + 2), y in [0, 1) of a 3 x 2 grid over [0, 3] x [0, 2] (cell = block,
// block 6 outside). Optionally a third abstraction made of polytope cells: a BSP over a wide
// domain whose reward region is the half-plane x + y <= 2.
struct NoisyCatalog {
  std::vector<std::uint32_t> axes{0, 1};
  std::vector<std::uint32_t> begin{0, 4, 7};
  std::vector<double> breaks{0, 1, 2, 3, 0, 1, 2};
  std::vector<std::uint32_t> cell_block{0, 1, 2, 3, 4, 5};
  std::vector<std::vector<double>> block_reward{{0, 0, 1, 0, 0, 0, 0}, {0, 0, 0, 0, 1, 0, 0}};
  std::vector<double> zeros = std::vector<double>(7, 0.0);
  std::vector<std::uint32_t> policy = std::vector<std::uint32_t>(7, 0);
  // The half-plane abstraction: domain [-10, 10]^2, one split x + y <= 2: cell 0 below
  // (reward 1), cell 1 above; block 2 outside.
  std::vector<double> wide_breaks{-10, 10, -10, 10};
  std::vector<std::uint32_t> wide_begin{0, 2, 4};
  std::vector<std::uint32_t> wide_cell_block{0, 1};
  std::vector<double> wide_reward{1, 0, 0};
  std::vector<double> normal{1, 1, 0, 0, 0, 0};
  std::vector<double> bound{2, 0, 0};
  std::vector<std::uint32_t> below{1, 0, 0};
  std::vector<std::uint32_t> above{2, 0, 0};
  std::vector<std::uint32_t> bsp_cell{rt::kInternalNode, 0, 1};
  std::vector<double> switching{0.8, 0.2, 0.2, 0.8};
  std::vector<double> prior{0.5, 0.5};
  std::vector<std::uint32_t> object_of{0, 0};
  std::vector<double> sigma{0.3, 0.0, 0.0};
  std::vector<double> detection{0.9};
  const char* actions[1] = {"stay"};
  const char* variables[2] = {"x", "y"};
  std::vector<rt::AbstractionView> abstractions;
  rt::CatalogView view;

  NoisyCatalog() {
    for (int k = 0; k < 2; ++k) {
      rt::AbstractionView abs;
      abs.context = k == 0 ? "first" : "second";
      abs.num_blocks = 7;
      abs.block_reward = block_reward[k].data();
      abs.reward = zeros.data();
      abs.policy = policy.data();
      abs.value = zeros.data();
      abs.grid = {2, axes.data(), begin.data(), breaks.data()};
      abs.cell_block = cell_block.data();
      abs.outside_block = 6;
      abstractions.push_back(abs);
    }
    rt::AbstractionView wide;
    wide.context = "half_plane";
    wide.num_blocks = 3;
    wide.block_reward = wide_reward.data();
    wide.reward = zeros.data();
    wide.policy = policy.data();
    wide.value = zeros.data();
    wide.grid = {2, axes.data(), wide_begin.data(), wide_breaks.data()};
    wide.cell_block = wide_cell_block.data();
    wide.outside_block = 2;
    wide.bsp = {3, 2, normal.data(), bound.data(), below.data(), above.data(), bsp_cell.data()};
    abstractions.push_back(wide);
    view.name = "noisy";
    view.compiler_version = "test";
    view.num_actions = 1;
    view.action_names = actions;
    view.num_abstractions = 2;  // the half-plane abstraction is used directly, not by filters
    view.switching = switching.data();
    view.prior = prior.data();
    view.abstractions = abstractions.data();
    view.observation.position = {1, object_of.data(), sigma.data(), detection.data()};
    view.state_dimension = 2;
    view.variable_names = variables;
  }
};

struct Integrator {
  std::vector<double> workspace;
  rt::RewardMass mass;
  explicit Integrator(const rt::CatalogView& catalog, rt::MassLimits limits = {})
      : workspace(rt::RewardMass::workspace_size(catalog) + 8),
        mass(catalog, limits, workspace.data()) {}
};

rt::MassResult reward_one(Integrator& integrator, const rt::AbstractionView& abs, double x,
                          double y) {
  const double state[2] = {x, y};
  integrator.mass.measure(state);
  return integrator.mass.match_mass(
      abs, state, [&](std::uint32_t block) { return abs.block_reward[block] == 1.0; });
}

TEST(RewardMass, TheCatalogIsValid) {
  NoisyCatalog catalog;
  std::string why;
  EXPECT_TRUE(rt::validate(catalog.view, &why)) << why;
  EXPECT_TRUE(catalog.view.has_noise_model());
  EXPECT_FALSE(catalog.view.has_robust_section());
}

TEST(RewardMass, ABoxRegionOnAGridIsAProductOfNormalCdfs) {
  NoisyCatalog catalog;
  Integrator integrator(catalog.view);
  for (const auto& [x, y] : {std::pair{1.5, 0.5}, {2.1, 0.2}, {0.4, 1.7}, {1.0, 1.0}}) {
    const double s = 0.3;
    const double expected =
        (phi((2 - x) / s) - phi((1 - x) / s)) * (phi((1 - y) / s) - phi((0 - y) / s));
    const rt::MassResult result = reward_one(integrator, catalog.abstractions[0], x, y);
    EXPECT_FALSE(result.missing);
    EXPECT_NEAR(result.probability, expected, 1e-8) << x << ", " << y;
    EXPECT_LT(result.error, 1e-8);  // the window's tails only: grids are exact
  }
}

TEST(RewardMass, SigmaGrowsWithTheObjectsMeasuredDistance) {
  NoisyCatalog catalog;
  catalog.sigma = {0.05, 0.1, 0.02};  // sigma(d) = 0.05 + 0.1 d + 0.02 d^2
  Integrator integrator(catalog.view);
  const double x = 1.2;
  const double y = 0.9;
  const double d = std::hypot(x, y);
  const double s = 0.05 + 0.1 * d + 0.02 * d * d;
  const rt::MassResult result = reward_one(integrator, catalog.abstractions[0], x, y);
  EXPECT_DOUBLE_EQ(integrator.mass.sigma(0), s);
  EXPECT_DOUBLE_EQ(integrator.mass.sigma(1), s);
  const double expected =
      (phi((2 - x) / s) - phi((1 - x) / s)) * (phi((1 - y) / s) - phi((0 - y) / s));
  EXPECT_NEAR(result.probability, expected, 1e-8);
}

TEST(RewardMass, ZeroSigmaIsAlgorithmOnesDeterministicDetection) {
  NoisyCatalog catalog;
  catalog.sigma = {0, 0, 0};
  Integrator integrator(catalog.view);
  EXPECT_EQ(reward_one(integrator, catalog.abstractions[0], 1.5, 0.5).probability, 1.0);
  EXPECT_EQ(reward_one(integrator, catalog.abstractions[0], 2.5, 0.5).probability, 0.0);
  EXPECT_EQ(reward_one(integrator, catalog.abstractions[0], 1.0, 0.0).probability, 1.0);  // faces
  EXPECT_EQ(reward_one(integrator, catalog.abstractions[0], 2.0, 0.5).probability, 0.0);
  EXPECT_EQ(reward_one(integrator, catalog.abstractions[0], -1.0, 0.5).probability, 0.0);
  EXPECT_EQ(reward_one(integrator, catalog.abstractions[0], 1.5, 0.5).boxes, 1U);
}

TEST(RewardMass, TheOutsideOfTheDomainCountsWithTheOutsideBlock) {
  NoisyCatalog catalog;
  Integrator integrator(catalog.view);
  // Matching the outside block only: the mass beyond [0, 3] x [0, 2].
  const double x = 0.2;
  const double y = 1.9;
  const double state[2] = {x, y};
  integrator.mass.measure(state);
  const rt::AbstractionView& abs = catalog.abstractions[0];
  const rt::MassResult outside =
      integrator.mass.match_mass(abs, state, [](std::uint32_t block) { return block == 6; });
  const double s = 0.3;
  const double inside = (phi((3 - x) / s) - phi(-x / s)) * (phi((2 - y) / s) - phi(-y / s));
  EXPECT_NEAR(outside.probability, 1 - inside, 1e-8);
}

TEST(RewardMass, PolytopeCellsAgreeWithTheClosedFormWithinTheReportedError) {
  NoisyCatalog catalog;
  Integrator integrator(catalog.view, {1e-5, 20000});
  const rt::AbstractionView& half_plane = catalog.abstractions[2];
  for (const auto& [x, y] : {std::pair{1.0, 1.0}, {0.9, 0.8}, {1.5, 0.7}, {-3.0, 2.0}}) {
    // x + y <= 2 with x, y independent N(mu, 0.3^2): X + Y ~ N(x + y, 2 * 0.09).
    const double expected = phi((2 - x - y) / (0.3 * std::sqrt(2.0)));
    const rt::MassResult result = reward_one(integrator, half_plane, x, y);
    EXPECT_LE(std::fabs(result.probability - expected), result.error + 1e-9) << x << ", " << y;
    EXPECT_LT(result.error, 0.02) << x << ", " << y;
    EXPECT_LT(result.boxes, 20100U);
  }
}

TEST(RewardMass, TheSameBoxAsPolytopeCellsMatchesTheGrid) {
  // Abstraction 0's reward box rebuilt as BSP cells over the grid's domain.
  NoisyCatalog catalog;
  std::vector<double> domain{0, 3, 0, 2};
  std::vector<std::uint32_t> domain_begin{0, 2, 4};
  // x <= 1 ? (cell 0) : (x <= 2 ? (y <= 1 ? cell 1 (reward) : cell 2) : cell 3)
  std::vector<double> normal{1, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0, 0, 0, 0};
  std::vector<double> bound{1, 0, 2, 1, 0, 0, 0};
  std::vector<std::uint32_t> below{1, 0, 3, 5, 0, 0, 0};
  std::vector<std::uint32_t> above{2, 0, 4, 6, 0, 0, 0};
  std::vector<std::uint32_t> cell{
      rt::kInternalNode, 0, rt::kInternalNode, rt::kInternalNode, 3, 1, 2};
  std::vector<std::uint32_t> cell_block{0, 1, 2, 3};
  std::vector<double> reward{0, 1, 0, 0, 0};
  rt::AbstractionView abs = catalog.abstractions[0];
  abs.num_blocks = 5;
  abs.block_reward = reward.data();
  abs.grid = {2, catalog.axes.data(), domain_begin.data(), domain.data()};
  abs.cell_block = cell_block.data();
  abs.outside_block = 4;
  abs.bsp = {7, 4, normal.data(), bound.data(), below.data(), above.data(), cell.data()};
  catalog.abstractions.push_back(abs);
  catalog.view.abstractions = catalog.abstractions.data();
  Integrator integrator(catalog.view);
  for (const auto& [x, y] : {std::pair{1.5, 0.5}, {2.1, 0.2}, {0.4, 1.7}}) {
    const double grid = reward_one(integrator, catalog.abstractions[0], x, y).probability;
    const rt::MassResult bsp = reward_one(integrator, catalog.abstractions[3], x, y);
    EXPECT_LE(std::fabs(bsp.probability - grid), bsp.error + 1e-9);
    EXPECT_LT(bsp.error, 1e-8);  // axis-aligned faces are cut exactly
  }
}

TEST(RewardMass, AMissedObjectIsReportedAndNothingComputed) {
  NoisyCatalog catalog;
  Integrator integrator(catalog.view);
  const rt::MassResult result = reward_one(integrator, catalog.abstractions[0], std::nan(""), 0.5);
  EXPECT_TRUE(result.missing);
  EXPECT_EQ(result.boxes, 0U);
}

struct Filter {
  std::vector<double> workspace;
  rt::AttentionFilter filter;
  Filter(const rt::CatalogView& catalog, rt::FilterMode mode)
      : workspace(rt::AttentionFilter::workspace_size(catalog, options(mode))),
        filter(catalog, options(mode), workspace.data(), workspace.size()) {}
  static rt::FilterOptions options(rt::FilterMode mode) {
    rt::FilterOptions options;
    options.mode = mode;
    return options;
  }
};

TEST(NoiseAwareFilter, AReadingJustPastTheRewardBoxStillExplainsTheReward) {
  // The robot gets reward 1 while its reading says x = 2.02: just inside the second
  // abstraction's box, but within 0.1 sigma of the first's. Algorithm 1 concludes "second"
  // with certainty; the noise-aware filter keeps both nearly even.
  NoisyCatalog catalog;
  Filter paper(catalog.view, rt::FilterMode::kPaper);
  Filter robust(catalog.view, rt::FilterMode::kNoiseAware);
  ASSERT_TRUE(robust.filter.ok());
  const double state[2] = {2.02, 0.5};
  for (Filter* f : {&paper, &robust}) {
    ASSERT_EQ(f->filter.start(state, 2), rt::StepStatus::kOk);
    ASSERT_EQ(f->filter.step(state, 2, 1.0, 0), rt::StepStatus::kOk);
  }
  EXPECT_EQ(paper.filter.belief(1), 1.0);
  const double s = 0.3;
  const double y_mass = phi(0.5 / s) - phi(-0.5 / s);
  const double first = (phi((2 - 2.02) / s) - phi((1 - 2.02) / s)) * y_mass;
  const double second = (phi((3 - 2.02) / s) - phi((2 - 2.02) / s)) * y_mass;
  EXPECT_NEAR(robust.filter.belief(0), first / (first + second), 1e-8);
  EXPECT_NEAR(robust.filter.reward_evidence(), 0.5 * first + 0.5 * second, 1e-8);
  EXPECT_LT(robust.filter.likelihood_error(), 1e-8);
}

TEST(NoiseAwareFilter, AMissedObjectOnlyPredicts) {
  NoisyCatalog catalog;
  Filter robust(catalog.view, rt::FilterMode::kNoiseAware);
  const double seen[2] = {1.5, 0.5};
  ASSERT_EQ(robust.filter.start(seen, 2), rt::StepStatus::kOk);
  ASSERT_EQ(robust.filter.step(seen, 2, 1.0, 0), rt::StepStatus::kOk);
  const double before = robust.filter.belief(0);
  const double missed[2] = {std::nan(""), std::nan("")};
  EXPECT_EQ(robust.filter.step(missed, 2, 1.0, 0), rt::StepStatus::kMissingObservation);
  EXPECT_NEAR(robust.filter.belief(0), 0.8 * before + 0.2 * (1 - before), 1e-12);
  EXPECT_EQ(robust.filter.action(), 0U);  // the outside block's policy
  // No reward observed (the robot could not tell): the same, with the reading in view.
  const double in_view = robust.filter.belief(0);
  EXPECT_EQ(robust.filter.step(seen, 2, std::nan(""), 0), rt::StepStatus::kMissingObservation);
  EXPECT_NEAR(robust.filter.belief(0), 0.8 * in_view + 0.2 * (1 - in_view), 1e-12);
}

TEST(NoiseAwareFilter, NeedsAPositionNoiseModel) {
  NoisyCatalog catalog;
  catalog.view.observation.position = {};
  Filter robust(catalog.view, rt::FilterMode::kNoiseAware);
  EXPECT_FALSE(robust.filter.ok());
  EXPECT_EQ(robust.filter.error(), rt::FilterError::kNoRobustSection);
}

// The discrete joint filter's mode is refused on a continuous catalog, by name.
TEST(NoiseAwareFilter, TheJointModeIsForDiscreteCatalogs) {
  NoisyCatalog catalog;
  Filter joint(catalog.view, rt::FilterMode::kJoint);
  EXPECT_EQ(joint.filter.error(), rt::FilterError::kWrongCatalogKind);
  EXPECT_EQ(rt::noise_model_mode(catalog.view), rt::FilterMode::kNoiseAware);
}

TEST(NoiseAwareFilter, ValidateRefusesABrokenNoiseModel) {
  NoisyCatalog catalog;
  std::string why;
  catalog.detection[0] = 0.0;
  EXPECT_FALSE(rt::validate(catalog.view, &why));
  EXPECT_NE(why.find("detection"), std::string::npos) << why;
  catalog.detection[0] = 1.0;
  catalog.sigma[0] = -0.1;
  EXPECT_FALSE(rt::validate(catalog.view, &why));
  catalog.sigma[0] = 0.1;
  catalog.object_of[1] = 3;
  EXPECT_FALSE(rt::validate(catalog.view, &why));
  catalog.object_of[1] = rt::kExactVariable;
  EXPECT_TRUE(rt::validate(catalog.view, &why)) << why;
}

}  // namespace
