// The continuous Go1 catalog linked through oasis_add_catalog() and the same spec's binary
// catalog loaded from a file take the same decisions on the same observed states: the
// grids, cell maps and policies survive both carriers alike. C++17 and the runtime only.

#include <cstdint>

#include <gtest/gtest.h>

#include "go1_treat_catalog.hpp"
#include "oasis/rt/attention_filter.hpp"
#include "oasis/rt/catalog_file.hpp"
#include "oasis/rt/catalog_validation.hpp"

namespace {

// Deterministic uniform numbers in [low, high) without <random>'s distributions.
struct Inputs {
  std::uint64_t state = 0x2545f4914f6cdd1dULL;
  double uniform(double low, double high) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return low + (high - low) * static_cast<double>(state >> 11) * 0x1p-53;
  }
};

TEST(Go1LinkedCatalog, LinkedAndLoadedTakeTheSameDecisions) {
  const oasis::rt::LoadedCatalog loaded =
      oasis::rt::LoadedCatalog::from_file(OASIS_GO1_CATALOG_FILE);
  ASSERT_TRUE(loaded.ok()) << loaded.error();
  const oasis::rt::CatalogView& linked = go1_treat::catalog();
  std::string why;
  ASSERT_TRUE(oasis::rt::validate(linked, &why)) << why;
  ASSERT_EQ(linked.state_dimension, 4U);
  EXPECT_EQ(loaded.view().spec_hash, linked.spec_hash);
  oasis::rt::FixedWorkspace<go1_treat::kNumAbstractions> work_linked;
  oasis::rt::FixedWorkspace<go1_treat::kNumAbstractions> work_loaded;
  oasis::rt::AttentionFilter from_linked(linked, {}, work_linked);
  oasis::rt::AttentionFilter from_file(loaded.view(), {}, work_loaded);
  ASSERT_TRUE(from_linked.ok() && from_file.ok());
  Inputs inputs;
  // Positions a little beyond the domain too ([0, 5] x [-3, 3] per human): the outside block.
  auto observe = [&inputs](double* state) {
    state[0] = inputs.uniform(-0.5, 5.5);
    state[1] = inputs.uniform(-3.5, 3.5);
    state[2] = inputs.uniform(-0.5, 5.5);
    state[3] = inputs.uniform(-3.5, 3.5);
  };
  double state[4];
  observe(state);
  ASSERT_EQ(from_linked.start(state, 4), from_file.start(state, 4));
  for (int t = 0; t < 2000; ++t) {
    ASSERT_EQ(from_linked.action(), from_file.action()) << "step " << t;
    const std::uint32_t action = from_linked.action();
    observe(state);
    const double reward = inputs.uniform(0, 1) < 0.3 ? 1.0 : 0.0;
    ASSERT_EQ(from_linked.step(state, 4, reward, action), from_file.step(state, 4, reward, action));
    ASSERT_EQ(from_linked.ml_abstraction(), from_file.ml_abstraction()) << "step " << t;
    ASSERT_EQ(from_linked.belief(0), from_file.belief(0)) << "step " << t;
  }
}

}  // namespace
