// Unit tests of model::TransitionStream (compiler/model/transition_stream.hpp): for edges given
// in choice order it must build the matrix TransitionBuilder builds, with the same pool ids
// (rows sorted stably by target, repeated targets merged, merged sums interned in choice order
// at the end), and refuse choices out of order.

#include "model/transition_stream.hpp"

#include <random>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

namespace oasis::model {
namespace {

struct Edge {
  StateIndex source;
  ActionIndex action;
  StateIndex target;
  ValueId probability;
};

// Rows of 0 to 6 edges over few targets, so that most repeat a target and many are unsorted.
std::vector<Edge> random_edges(std::uint32_t states, std::uint32_t actions, RationalPool& values,
                               unsigned seed) {
  std::mt19937 random(seed);
  std::vector<ValueId> probabilities;
  for (long d : {2, 3, 4, 5, 7, 8})
    probabilities.push_back(values.intern(Rational(1, d)));
  std::vector<Edge> edges;
  for (StateIndex s = 0; s < states; ++s) {
    for (ActionIndex a = 0; a < actions; ++a) {
      const auto length = random() % 7;
      for (std::uint32_t e = 0; e < length; ++e) {
        edges.push_back({s, a, static_cast<StateIndex>(random() % 4),
                         probabilities[random() % probabilities.size()]});
      }
    }
  }
  return edges;
}

void expect_same(const TransitionMatrix& a, const TransitionMatrix& b) {
  EXPECT_EQ(a.num_states, b.num_states);
  EXPECT_EQ(a.num_actions, b.num_actions);
  EXPECT_EQ(a.choice_begin, b.choice_begin);
  EXPECT_EQ(a.edge_target, b.edge_target);
  EXPECT_EQ(a.edge_probability, b.edge_probability);
}

TEST(TransitionStream, BuildsWhatTheBuilderBuildsWithTheSamePoolIds) {
  for (unsigned seed = 1; seed <= 20; ++seed) {
    constexpr std::uint32_t kStates = 40;
    constexpr std::uint32_t kActions = 3;
    RationalPool built_values;
    const std::vector<Edge> edges = random_edges(kStates, kActions, built_values, seed);
    RationalPool streamed_values = built_values;

    TransitionBuilder builder(kStates, kActions);
    for (const Edge& edge : edges)
      builder.add(edge.source, edge.action, edge.target, edge.probability);
    const TransitionMatrix built = builder.finish(built_values);

    TransitionStream stream(kActions, streamed_values);
    for (std::size_t e = 0; e < edges.size(); ++e) {
      const Edge& edge = edges[e];
      if (e == 0 || edges[e - 1].source != edge.source || edges[e - 1].action != edge.action)
        stream.begin(edge.source * kActions + edge.action);
      stream.add(edge.target, edge.probability);
    }
    const TransitionMatrix streamed = stream.finish(kStates, streamed_values);

    expect_same(built, streamed);
    ASSERT_EQ(built_values.size(), streamed_values.size()) << "seed " << seed;
    for (ValueId id = 0; id < built_values.size(); ++id)
      EXPECT_EQ(built_values[id], streamed_values[id]) << "seed " << seed << ", id " << id;
  }
}

TEST(TransitionStream, SkippedChoicesAndTrailingStatesHaveNoEdges) {
  RationalPool values;
  TransitionStream stream(2, values);
  stream.begin(3);  // state 1, action 1
  stream.add(0, RationalPool::kOne);
  const TransitionMatrix matrix = stream.finish(3, values);
  EXPECT_EQ(matrix.choice_begin, (std::vector<EdgeIndex>{0, 0, 0, 0, 1, 1, 1}));
  EXPECT_TRUE(matrix.enabled(1, 1));
  EXPECT_FALSE(matrix.enabled(2, 0));
}

TEST(TransitionStream, RefusesChoicesOutOfOrder) {
  RationalPool values;
  TransitionStream stream(2, values);
  stream.begin(2);
  stream.add(0, RationalPool::kOne);
  EXPECT_THROW(stream.begin(2), std::logic_error);
  EXPECT_THROW(stream.begin(1), std::logic_error);
}

}  // namespace
}  // namespace oasis::model
