// Unit tests of model::TransitionStream (compiler/model/transition_stream.hpp): for edges given
// in choice order it must build the matrix TransitionBuilder builds, with the same pool ids
// (rows sorted stably by target, repeated targets merged, merged sums interned in choice order
// at the end), and refuse choices out of order; its choices must move to their indices when
// the number of actions changes during the stream (PRISM's actions are numbered as found).

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

// Streams `edges` (in choice order for `actions` actions) with the stream's action count
// changed on the way: `count_before(a)` is the count set before the first choice of action a
// that the count does not cover yet; the true count is set at the end.
template <typename CountBefore>
TransitionMatrix stream_with_changing_count(const std::vector<Edge>& edges, std::uint32_t states,
                                            std::uint32_t actions, std::uint32_t initial_count,
                                            CountBefore count_before, RationalPool& values) {
  TransitionStream stream(initial_count, values);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const Edge& edge = edges[e];
    if (e == 0 || edges[e - 1].source != edge.source || edges[e - 1].action != edge.action) {
      if (edge.action >= stream.num_actions()) stream.set_num_actions(count_before(edge.action));
      stream.begin(edge.source * stream.num_actions() + edge.action);
    }
    stream.add(edge.target, edge.probability);
  }
  stream.set_num_actions(actions);
  return stream.finish(states, values);
}

TEST(TransitionStream, MovesChoicesWhenTheActionCountChanges) {
  for (unsigned seed = 1; seed <= 20; ++seed) {
    constexpr std::uint32_t kStates = 40;
    constexpr std::uint32_t kActions = 5;
    RationalPool values;
    // Actions 3 and 4 are first used from states 10 and 25 on.
    std::vector<Edge> edges;
    for (const Edge& edge : random_edges(kStates, kActions, values, seed)) {
      if ((edge.action == 3 && edge.source < 10) || (edge.action == 4 && edge.source < 25))
        continue;
      edges.push_back(edge);
    }
    TransitionBuilder builder(kStates, kActions);
    for (const Edge& edge : edges)
      builder.add(edge.source, edge.action, edge.target, edge.probability);
    RationalPool built_values = values;
    const TransitionMatrix built = builder.finish(built_values);

    // Growing one action at a time, growing ahead (twice as many), and shrinking at the end.
    RationalPool exact_values = values;
    expect_same(
        built, stream_with_changing_count(
                   edges, kStates, kActions, 1, [](ActionIndex a) { return a + 1; }, exact_values));
    RationalPool ahead_values = values;
    expect_same(built, stream_with_changing_count(
                           edges, kStates, kActions, 1, [](ActionIndex a) { return 2 * (a + 1); },
                           ahead_values));
    RationalPool wide_values = values;
    expect_same(built,
                stream_with_changing_count(
                    edges, kStates, kActions, 9, [](ActionIndex a) { return a + 1; }, wide_values));
  }
}

TEST(TransitionStream, RefusesFewerActionsThanItsChoicesUse) {
  RationalPool values;
  TransitionStream stream(3, values);
  stream.begin(2);  // state 0, action 2
  stream.add(0, RationalPool::kOne);
  stream.begin(3);  // state 1, action 0
  stream.add(0, RationalPool::kOne);
  EXPECT_THROW(stream.set_num_actions(2), std::logic_error);
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
