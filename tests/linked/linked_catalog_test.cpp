// A catalog linked through oasis_add_catalog() and the same spec's binary catalog loaded
// from a file must be the same catalog and take the same decisions on the same inputs.
// C++17 and the runtime only, as a robot program would be.

#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "discrete_tracking_catalog.hpp"
#include "oasis/rt/attention_filter.hpp"
#include "oasis/rt/catalog_file.hpp"
#include "oasis/rt/catalog_validation.hpp"

namespace {

// Deterministic inputs without <random>'s distributions.
struct Inputs {
  std::uint64_t state = 0x9e3779b97f4a7c15ULL;
  std::uint32_t next(std::uint32_t bound) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<std::uint32_t>((state >> 33) % bound);
  }
};

TEST(LinkedCatalog, IsValidAndSizedAsDeclared) {
  const oasis::rt::CatalogView& linked = discrete_tracking::catalog();
  std::string why;
  ASSERT_TRUE(oasis::rt::validate(linked, &why)) << why;
  EXPECT_EQ(linked.num_states, discrete_tracking::kNumStates);
  EXPECT_EQ(linked.num_abstractions, discrete_tracking::kNumAbstractions);
}

TEST(LinkedCatalog, LinkedAndLoadedTakeTheSameDecisions) {
  const oasis::rt::LoadedCatalog loaded = oasis::rt::LoadedCatalog::from_file(OASIS_CATALOG_FILE);
  ASSERT_TRUE(loaded.ok()) << loaded.error();
  const oasis::rt::CatalogView& linked = discrete_tracking::catalog();
  EXPECT_EQ(loaded.view().spec_hash, linked.spec_hash);
  for (const auto tie_rule : {oasis::rt::TieRule::kKeep, oasis::rt::TieRule::kRandom}) {
    oasis::rt::FilterOptions options;
    options.tie_rule = tie_rule;
    options.seed = 5;
    oasis::rt::FixedWorkspace<discrete_tracking::kNumAbstractions> work_linked;
    oasis::rt::FixedWorkspace<discrete_tracking::kNumAbstractions> work_loaded;
    oasis::rt::AttentionFilter from_linked(linked, options, work_linked);
    oasis::rt::AttentionFilter from_file(loaded.view(), options, work_loaded);
    ASSERT_TRUE(from_linked.ok() && from_file.ok());
    from_linked.start(0);
    from_file.start(0);
    Inputs inputs;
    for (int t = 0; t < 1000; ++t) {
      ASSERT_EQ(from_linked.action(), from_file.action()) << "step " << t;
      const std::uint32_t state = inputs.next(discrete_tracking::kNumStates);
      const double reward = inputs.next(2);
      const std::uint32_t action = from_linked.action();
      ASSERT_EQ(from_linked.step(state, reward, action), from_file.step(state, reward, action));
      ASSERT_EQ(from_linked.ml_abstraction(), from_file.ml_abstraction()) << "step " << t;
      ASSERT_EQ(from_linked.belief(0), from_file.belief(0)) << "step " << t;
    }
  }
}

}  // namespace
