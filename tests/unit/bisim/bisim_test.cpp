// The bisimulation engine on cases with known answers: the paper's example, its three
// arithmetic modes against each other and against the naive reference, a model whose
// denominators force exact rational sums, the --epsilon mode, and quotients that survive an
// export to .aut and PRISM files and an import.

#include <filesystem>
#include <sstream>

#include <gtest/gtest.h>

#include "../../support/naive_bisimulation.hpp"
#include "../../support/random_mdp.hpp"
#include "../../support/scratch_directory.hpp"
#include "../../support/spec_models.hpp"
#include "bisim/quotient.hpp"
#include "bisim/refinement.hpp"
#include "formats/aut_writer.hpp"
#include "formats/explicit_writer.hpp"
#include "formats/model_file.hpp"
#include "frontend/load_spec.hpp"
#include "model/explorer.hpp"
#include "verify/verifier.hpp"

namespace oasis {
namespace {

using model::ExplicitModel;
using model::Partition;
using test::explore_spec_file;
using test::explore_spec_text;

std::vector<std::vector<std::string>> named_blocks(const ExplicitModel& model,
                                                   const Partition& partition) {
  std::vector<std::vector<std::string>> result;
  for (const auto& block : partition.blocks()) {
    result.emplace_back();
    for (model::StateIndex s : block)
      result.back().push_back(model.states.name(s));
  }
  return result;
}

TEST(Bisimulation, PaperExampleGivesTheTwoAbstractions) {
  const ExplicitModel model =
      explore_spec_file(std::string(OASIS_SOURCE_DIR) + "/specs/discrete_tracking.oasis");
  ASSERT_EQ(model.contexts[0].name, "object_at_s3");
  ASSERT_EQ(model.contexts[1].name, "object_at_s1");
  using Blocks = std::vector<std::vector<std::string>>;
  EXPECT_EQ(named_blocks(model, bisim::coarsest_bisimulation(model, 0)),
            (Blocks{{"s1", "s2"}, {"s3"}}));
  EXPECT_EQ(named_blocks(model, bisim::coarsest_bisimulation(model, 1)),
            (Blocks{{"s1"}, {"s2", "s3"}}));
}

TEST(Bisimulation, QuotientOfThePaperExample) {
  const ExplicitModel model =
      explore_spec_file(std::string(OASIS_SOURCE_DIR) + "/specs/discrete_tracking.oasis");
  const Partition partition = bisim::coarsest_bisimulation(model, 0);
  const ExplicitModel quotient = bisim::build_quotient(model, 0, partition);
  ASSERT_EQ(quotient.num_states(), 2U);
  EXPECT_FALSE(model::find_structural_problem(quotient));
  const auto& matrix = *quotient.contexts[0].transitions;
  // z0 = {s1, s2}, z1 = {s3}. From z0, R moves to z1 with probability 1/2 (s1: to s3 with
  // 1/2; s2: to s3 with 1/2); L stays in z0.
  const model::ActionIndex right = 1;
  ASSERT_EQ(matrix.edges_end(0, right) - matrix.edges_begin(0, right), 2U);
  EXPECT_EQ(quotient.values[matrix.edge_probability[matrix.edges_begin(0, right) + 1]],
            Rational(1, 2));
  EXPECT_EQ(quotient.reward(0, 1, 0), 1);
  EXPECT_EQ(quotient.reward(0, 0, 0), 0);
}

// Integer sums over a common denominator and GMP sums are two exact routes: they must agree
// with each other and with the naive reference on every random model.
TEST(Bisimulation, IntegerAndRationalSumsAgree) {
  bisim::RefinementOptions rational;
  rational.rational_sums = true;
  for (std::uint64_t seed = 1; seed <= 600; ++seed) {
    const ExplicitModel model = test::random_mdp(seed);
    for (std::size_t c = 0; c < model.contexts.size(); ++c) {
      bisim::RefinementStatistics statistics;
      const Partition fast = bisim::coarsest_bisimulation(model, c, {}, &statistics);
      EXPECT_TRUE(statistics.exact_integer_sums);
      const Partition slow = bisim::coarsest_bisimulation(model, c, rational);
      const Partition naive = test::naive_bisimulation(model, c);
      ASSERT_EQ(fast.block_of, naive.block_of) << "seed " << seed;
      ASSERT_EQ(slow.block_of, naive.block_of) << "seed " << seed;
    }
  }
}

// Probabilities with huge coprime denominators: no common denominator fits in 64 bits, so
// the engine must fall back to exact rational sums by itself.
TEST(Bisimulation, HugeDenominatorsUseRationalSums) {
  const ExplicitModel model = explore_spec_text(R"(
mdp huge {
  states a, b, c, goal;
  actions go;
  const p = 1/1000000007;
  const q = 1/998244353;
  const r = 1/1000000009;
  a, go -> p: goal + q: c + (1 - p - q): a;
  b, go -> p: goal + q: c + (1 - p - q): b;
  c, go -> r: goal + (1 - r): c;
  goal, go -> goal;
  reward goal : 1;
}
)");
  bisim::RefinementStatistics statistics;
  const Partition partition = bisim::coarsest_bisimulation(model, 0, {}, &statistics);
  EXPECT_FALSE(statistics.exact_integer_sums);
  using Blocks = std::vector<std::vector<std::string>>;
  EXPECT_EQ(named_blocks(model, partition), (Blocks{{"a", "b"}, {"c"}, {"goal"}}));
  EXPECT_TRUE(verify::verify_partition(model, 0, partition).ok());
}

// With a rounding step far below the models' smallest probability gap (1/24 for denominators up
// to 8 and 3), rounding changes nothing: the approximate mode must give the exact answer.
TEST(Bisimulation, TinyEpsilonMatchesExactOnExactModels) {
  bisim::RefinementOptions rounded;
  rounded.rounding_step = 1e-9;
  for (std::uint64_t seed = 1; seed <= 300; ++seed) {
    const ExplicitModel model = test::random_mdp(seed);
    for (std::size_t c = 0; c < model.contexts.size(); ++c) {
      ASSERT_EQ(bisim::coarsest_bisimulation(model, c, rounded).block_of,
                bisim::coarsest_bisimulation(model, c).block_of)
          << "seed " << seed;
    }
  }
}

// Floating-point noise: 0.1 + 0.2 written as 0.30000000000000004. Exact mode separates the
// two states; --epsilon 1e-9 merges them, which is what the mode is for.
TEST(Bisimulation, EpsilonAbsorbsFloatingPointNoise) {
  const ExplicitModel model = explore_spec_text(R"(
mdp noisy {
  states a, b, goal, other;
  actions go;
  a, go -> 0.30000000000000004: goal + 0.69999999999999996: other;
  b, go -> 0.3: goal + 0.7: other;
  goal, go -> goal;
  other, go -> other;
  reward goal : 1;
}
)");
  EXPECT_EQ(bisim::coarsest_bisimulation(model, 0).num_blocks, 4U);
  bisim::RefinementOptions rounded;
  rounded.rounding_step = 1e-9;
  EXPECT_EQ(bisim::coarsest_bisimulation(model, 0, rounded).num_blocks, 3U);
}

// Export each context to .aut and PRISM, import it, and quotient again: the same partition.
TEST(Bisimulation, ImportedModelsGiveTheSameQuotient) {
  const test::ScratchDirectory scratch("oasis_bisim_import");
  const std::filesystem::path& directory = scratch.path();
  std::size_t prism_compared = 0;
  std::size_t aut_compared = 0;
  for (std::uint64_t seed = 1; seed <= 80; ++seed) {
    test::RandomMdpOptions options;
    const ExplicitModel model = test::random_mdp(seed, options);
    for (std::size_t c = 0; c < model.contexts.size(); ++c) {
      const Partition original = bisim::coarsest_bisimulation(model, c);
      std::string error;
      const std::string aut = (directory / "m.aut").string();
      const std::string prism = (directory / "m").string();
      ASSERT_TRUE(formats::write_prism(model, c, prism, error)) << error;
      {
        SourceManager sources;
        std::ostringstream messages;
        DiagnosticEngine diagnostics(sources, messages);
        const auto imported = formats::read_model_file(prism + ".tra", sources, diagnostics, {});
        ASSERT_TRUE(imported) << messages.str();
        EXPECT_EQ(bisim::coarsest_bisimulation(*imported, 0).block_of, original.block_of)
            << "seed " << seed;
        ++prism_compared;
      }
      // .aut cannot carry the state reward of a state with no enabled action
      // (docs/formats.md), so compare only models where that cannot matter.
      bool has_deadlock = false;
      for (model::StateIndex s = 0; s < model.num_states(); ++s) {
        bool any = false;
        for (model::ActionIndex a = 0; a < model.num_actions(); ++a)
          any |= model.contexts[c].transitions->enabled(s, a);
        has_deadlock |= !any;
      }
      if (has_deadlock || !formats::write_aut_file(model, c, aut, error)) continue;
      SourceManager sources;
      std::ostringstream messages;
      DiagnosticEngine diagnostics(sources, messages);
      const auto imported = formats::read_model_file(aut, sources, diagnostics, {});
      ASSERT_TRUE(imported) << messages.str();
      if (imported->num_states() != model.num_states()) continue;  // trailing unreached states
      // Actions are renumbered by appearance in .aut; the partition does not depend on it.
      EXPECT_EQ(bisim::coarsest_bisimulation(*imported, 0).block_of, original.block_of)
          << "seed " << seed;
      ++aut_compared;
    }
  }
  EXPECT_GE(prism_compared, 40U);
  EXPECT_GE(aut_compared, 20U) << "too few models could go through .aut for the test to mean much";
}

}  // namespace
}  // namespace oasis
