// The reverse edges refinement walks: every edge of the matrix appears exactly once, under its
// target, with its choice and probability, in both record layouts; and the layout is the
// packed one exactly when choice and probability id fit in 32 bits together.

#include "bisim/incoming_edges.hpp"

#include <algorithm>
#include <cstdint>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "../../support/random_mdp.hpp"

namespace oasis {
namespace {

using model::ChoiceIndex;
using model::EdgeIndex;
using model::StateIndex;
using model::TransitionMatrix;

using Record = std::tuple<StateIndex, ChoiceIndex, ValueId>;  // target, choice, probability

std::vector<Record> forward_records(const TransitionMatrix& matrix) {
  std::vector<Record> records;
  for (ChoiceIndex c = 0; c + 1 < matrix.choice_begin.size(); ++c) {
    for (EdgeIndex e = matrix.choice_begin[c]; e < matrix.choice_begin[c + 1]; ++e)
      records.emplace_back(matrix.edge_target[e], c, matrix.edge_probability[e]);
  }
  std::sort(records.begin(), records.end());
  return records;
}

std::vector<Record> reverse_records(const TransitionMatrix& matrix,
                                    const bisim::IncomingEdges& incoming) {
  std::vector<Record> records;
  for (StateIndex t = 0; t < matrix.num_states; ++t) {
    for (EdgeIndex e = incoming.begin(t); e < incoming.end(t); ++e)
      records.emplace_back(t, incoming.choice(e), incoming.probability(e));
  }
  std::sort(records.begin(), records.end());
  return records;
}

TEST(IncomingEdges, EveryEdgeOnceUnderItsTargetInBothLayouts) {
  for (std::uint64_t seed = 1; seed <= 300; ++seed) {
    const model::ExplicitModel model = test::random_mdp(seed);
    const TransitionMatrix& matrix = *model.contexts.front().transitions;
    const bisim::IncomingEdges packed(matrix);
    const bisim::IncomingEdges wide(matrix, /*allow_packed=*/false);
    EXPECT_TRUE(packed.packed()) << "seed " << seed;  // small models always fit
    EXPECT_FALSE(wide.packed());
    ASSERT_EQ(packed.size(), matrix.num_edges());
    ASSERT_EQ(wide.size(), matrix.num_edges());
    const std::vector<Record> expected = forward_records(matrix);
    EXPECT_EQ(reverse_records(matrix, packed), expected) << "seed " << seed;
    EXPECT_EQ(reverse_records(matrix, wide), expected) << "seed " << seed;
  }
}

// 2^16 choices need 16 bits; a probability id of 2^16 needs 17: together 33, so the records
// must be wide, and a probability id one smaller makes them fit.
TEST(IncomingEdges, PacksOnlyWhenChoiceAndProbabilityFitIn32Bits) {
  TransitionMatrix matrix;
  matrix.num_states = 1U << 14;
  matrix.num_actions = 4;
  matrix.choice_begin.assign(std::size_t{matrix.num_states} * matrix.num_actions + 1, 1);
  matrix.choice_begin.front() = 0;
  matrix.edge_target = {matrix.num_states - 1};
  matrix.edge_probability = {ValueId{1} << 16U};
  EXPECT_FALSE(bisim::IncomingEdges(matrix).packed());
  matrix.edge_probability = {(ValueId{1} << 16U) - 1};
  const bisim::IncomingEdges fits(matrix);
  ASSERT_TRUE(fits.packed());
  EXPECT_EQ(fits.choice(0), 0U);
  EXPECT_EQ(fits.probability(0), (ValueId{1} << 16U) - 1);
  EXPECT_EQ(fits.begin(matrix.num_states - 1), 0U);
  EXPECT_EQ(fits.end(matrix.num_states - 1), 1U);
}

}  // namespace
}  // namespace oasis
