// A continuous catalog in the runtime's schema: it validates, survives the binary file, the
// filter runs on state vectors and follows whichever human the rewards point at, and damaged
// files never break the loader.

#include "pipeline/continuous_catalog.hpp"

#include <cstring>
#include <random>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "../../support/spec_models.hpp"
#include "codegen/binary_catalog.hpp"
#include "oasis/rt/attention_filter.hpp"
#include "oasis/rt/catalog_file.hpp"
#include "oasis/rt/catalog_validation.hpp"
#include "pipeline/continuous_catalog_data.hpp"

namespace oasis {
namespace {

// The Go1 spec's catalog at a coarse epsilon (quick), built once for all tests.
const pipeline::ContinuousCatalog& go1_catalog() {
  static const pipeline::ContinuousCatalog catalog = [] {
    const model::ModelIR ir = test::shipped_go1_spec();
    pipeline::ContinuousCatalogOptions options;
    options.abstraction.target.epsilon = 0.3;
    std::string error;
    auto built = pipeline::build_continuous_catalog(ir, 99, options, error);
    EXPECT_TRUE(built) << error;
    return std::move(*built);
  }();
  return catalog;
}

rt::LoadedCatalog load(const std::string& bytes) {
  return rt::LoadedCatalog::from_bytes(bytes.data(), bytes.size());
}

TEST(ContinuousCatalogData, ValidatesWithAndWithoutTransitions) {
  for (const bool transitions : {false, true}) {
    model::CatalogData data = pipeline::continuous_catalog_data(go1_catalog(), transitions);
    const rt::CatalogView view = data.view();
    std::string why;
    EXPECT_TRUE(rt::validate(view, &why)) << why;
    EXPECT_TRUE(view.is_continuous());
    EXPECT_EQ(view.state_dimension, 4U);
    EXPECT_STREQ(view.variable_names[2], "x2");
    EXPECT_EQ(view.abstractions[0].grid.dimension, 2U);
    EXPECT_EQ(view.abstractions[0].grid.axes[0], 0U);  // x1
    EXPECT_EQ(view.abstractions[1].grid.axes[0], 2U);  // x2
    EXPECT_EQ(view.abstractions[0].quotient.choice_begin != nullptr, transitions);
    EXPECT_GE(view.abstractions[0].epsilon,
              pipeline::bound_as_double(go1_catalog().abstractions[0].epsilon));
  }
}

// Human 1 holds the treat in reach for a while, then human 2 takes it and comes into reach
// while human 1 walks away: the ML abstraction follows.
TEST(ContinuousCatalogData, TheFilterFollowsTheTreatAndTheLoadedFileDecidesTheSame) {
  model::CatalogData data = pipeline::continuous_catalog_data(go1_catalog(), false);
  const rt::CatalogView memory = data.view();
  const rt::LoadedCatalog file = load(codegen::binary_catalog(data));
  ASSERT_TRUE(file.ok()) << file.error();
  std::vector<double> work_memory(rt::AttentionFilter::workspace_size(memory, {}));
  std::vector<double> work_file(rt::AttentionFilter::workspace_size(file.view(), {}));
  rt::AttentionFilter in_memory(memory, {}, work_memory.data(), work_memory.size());
  rt::AttentionFilter loaded(file.view(), {}, work_file.data(), work_file.size());
  ASSERT_TRUE(in_memory.ok() && loaded.ok());
  double state[4] = {0.5, 0.0, 3.0, 2.0};  // x1, y1, x2, y2
  ASSERT_EQ(in_memory.start(state, 4), rt::StepStatus::kOk);
  loaded.start(state, 4);
  for (int t = 0; t < 5; ++t) {
    const std::uint32_t action = in_memory.action();
    ASSERT_NE(action, rt::kNoAction);
    ASSERT_EQ(loaded.action(), action);
    EXPECT_EQ(in_memory.step(state, 4, 1.0, action), rt::StepStatus::kOk);
    loaded.step(state, 4, 1.0, action);
  }
  EXPECT_EQ(in_memory.ml_abstraction(), 0U);
  const double handed_over[4] = {3.0, -2.0, 0.6, 0.1};
  for (int t = 0; t < 5; ++t) {
    const std::uint32_t action = in_memory.action();
    ASSERT_EQ(loaded.action(), action);
    in_memory.step(handed_over, 4, 1.0, action);
    loaded.step(handed_over, 4, 1.0, action);
    ASSERT_EQ(loaded.ml_abstraction(), in_memory.ml_abstraction());
  }
  EXPECT_EQ(in_memory.ml_abstraction(), 1U);
  // Index-based calls are refused on a continuous catalog, and short vectors too.
  EXPECT_EQ(in_memory.step(0U, 1.0, 0U), rt::StepStatus::kBadState);
  EXPECT_EQ(in_memory.step(handed_over, 3, 1.0, 0), rt::StepStatus::kBadState);
}

TEST(ContinuousCatalogData, AStateOutsideTheDomainIsInTheOutsideBlock) {
  model::CatalogData data = pipeline::continuous_catalog_data(go1_catalog(), false);
  const rt::CatalogView view = data.view();
  std::vector<double> work(rt::AttentionFilter::workspace_size(view, {}));
  rt::AttentionFilter filter(view, {}, work.data(), work.size());
  const double far[4] = {9.0, 0.0, 9.0, 0.0};  // both humans beyond 5 m
  ASSERT_EQ(filter.start(far, 4), rt::StepStatus::kOk);
  EXPECT_EQ(filter.abstract_state(), view.abstractions[filter.ml_abstraction()].outside_block);
}

TEST(ContinuousCatalogData, DamagedFilesNeverBreakTheLoader) {
  model::CatalogData data = pipeline::continuous_catalog_data(go1_catalog(), false);
  const std::string good = codegen::binary_catalog(data);
  ASSERT_TRUE(load(good).ok()) << load(good).error();
  std::mt19937 random(5);
  int accepted = 0;
  for (int trial = 0; trial < 300; ++trial) {
    std::string bad = good;
    // Mostly the header and the section table, where the grid's sizes live.
    for (int f = 0; f < 2; ++f) {
      const std::size_t span = trial % 2 == 0 ? 64 + 40 * 24 : bad.size() - 32;
      const std::size_t at = 32 + random() % std::min(span, bad.size() - 32);
      bad[at] = static_cast<char>(bad[at] ^ static_cast<char>(1U << (random() % 8)));
    }
    const std::uint64_t checksum =
        rt::fnv1a64(reinterpret_cast<const unsigned char*>(bad.data()) + 32, bad.size() - 32);
    std::memcpy(bad.data() + 24, &checksum, sizeof checksum);
    const rt::LoadedCatalog loaded = load(bad);
    if (!loaded.ok()) continue;
    ++accepted;
    std::string why;
    ASSERT_TRUE(rt::validate(loaded.view(), &why)) << why;
    std::vector<double> work(rt::AttentionFilter::workspace_size(loaded.view(), {}));
    rt::AttentionFilter filter(loaded.view(), {}, work.data(), work.size());
    const double state[4] = {0.5, 0.1, 2.0, -1.0};
    filter.start(state, 4);
    filter.step(state, 4, 1.0, 0);
  }
  EXPECT_GT(accepted, 0);
}

}  // namespace
}  // namespace oasis
