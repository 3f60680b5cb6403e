// The proof by invariants that no two states are bisimilar (bisim/discrete_proof.hpp), against
// the naive signature fixpoint on 2000 seeded random MDPs: whenever it says
// "discrete", the coarsest bisimulation must be discrete; when two states are bisimilar it
// must never say so; and it must say so often enough to be worth having.

#include "bisim/discrete_proof.hpp"

#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../../support/naive_bisimulation.hpp"
#include "../../support/random_mdp.hpp"

namespace oasis {
namespace {

// Sanitizers make everything ~10x slower; fewer models keep that run short.
#if defined(__SANITIZE_ADDRESS__)
constexpr std::uint64_t kModels = 500;
#else
constexpr std::uint64_t kModels = 2000;
#endif

// A context of an explicit model as the proof reads it. Bisimilar states share whether each
// action is enabled and R(s, a) for every action (R(s) for dead ends); a fixed combination of
// those is a number they share, and a disabled action's expectation is 0 for both.
struct CsrInvariants {
  bisim::InvariantModel model;
  std::vector<double> probability;  // per edge
};

CsrInvariants invariants_of(const model::ExplicitModel& mdp, std::size_t context) {
  const model::TransitionMatrix& matrix = *mdp.contexts[context].transitions;
  CsrInvariants out;
  for (model::EdgeIndex e = 0; e < matrix.num_edges(); ++e)
    out.probability.push_back(to_double(mdp.values[matrix.edge_probability[e]]));
  bisim::InvariantModel& model = out.model;
  model.num_states = mdp.num_states();
  model.num_actions = mdp.num_actions();
  model.smallest_term = 1;
  for (const double p : out.probability)
    model.smallest_term = std::min(model.smallest_term, p);
  std::uint32_t longest = 0;
  for (model::StateIndex s = 0; s < mdp.num_states(); ++s) {
    bool live = false;
    double reward = 0;
    for (model::ActionIndex a = 0; a < mdp.num_actions(); ++a) {
      longest = std::max(longest, matrix.edges_end(s, a) - matrix.edges_begin(s, a));
      if (!matrix.enabled(s, a)) continue;
      live = true;
      reward += (a + 1.5) * to_double(mdp.reward(context, s, a));
    }
    const double state = to_double(mdp.values[mdp.contexts[context].rewards.state[s]]);
    model.reward.push_back(live ? reward : 1000 + state);
  }
  model.rounding_depth = longest + 2;
  const double* p = out.probability.data();
  model.expectation = [&matrix, p](std::uint32_t s, std::uint32_t a, const double* x) {
    double sum = 0;
    for (model::EdgeIndex e = matrix.edges_begin(s, a); e < matrix.edges_end(s, a); ++e)
      sum += p[e] * x[matrix.edge_target[e]];
    return sum;
  };
  return out;
}

TEST(DiscreteProof, NeverClaimsDiscreteWhenTwoStatesAreBisimilar) {
  std::uint32_t proven = 0;
  std::uint32_t discrete = 0;
  for (std::uint64_t seed = 1; seed <= kModels; ++seed) {
    const model::ExplicitModel mdp = test::random_mdp(seed);
    const model::Partition coarsest = test::naive_bisimulation(mdp, 0);
    const CsrInvariants invariants = invariants_of(mdp, 0);
    const bisim::DiscreteProof proof = bisim::prove_discrete(invariants.model);
    const bool truly_discrete = coarsest.num_blocks == mdp.num_states();
    discrete += truly_discrete ? 1 : 0;
    if (proof.discrete) {
      ++proven;
      EXPECT_TRUE(truly_discrete) << "seed " << seed << ": " << coarsest.num_blocks << " blocks of "
                                  << mdp.num_states() << " states";
    }
    EXPECT_GE(proof.groups, 1U);
    EXPECT_LE(proof.groups, coarsest.num_blocks) << "seed " << seed;
  }
  // Planted structures make most models coarser; of the discrete ones, the proof must find
  // most (it only gives up where a linear combination of actions hides a difference).
  EXPECT_GT(discrete, kModels / 40);
  EXPECT_GE(proven * 10, discrete * 8) << proven << " proven of " << discrete;
}

TEST(DiscreteProof, TwoMirroredStatesStayTogether) {
  // 0 and 1 both go to 2 or 3 with probability 1/2 each; 2 is rewarded, 3 is not.
  bisim::InvariantModel model;
  model.num_states = 4;
  model.num_actions = 1;
  model.reward = {0, 0, 1, 0};
  model.rounding_depth = 4;
  model.smallest_term = 0.5;
  model.expectation = [](std::uint32_t s, std::uint32_t /*a*/, const double* x) {
    return s < 2 ? 0.5 * x[2] + 0.5 * x[3] : x[s];
  };
  const bisim::DiscreteProof proof = bisim::prove_discrete(model);
  EXPECT_FALSE(proof.discrete);
  EXPECT_EQ(proof.groups, 3U);  // {0, 1}, {2}, {3}
}

TEST(DiscreteProof, ValuesCloserThanTheirRoundingAreNotToldApart) {
  // Two states whose single steps differ by less than the bound on rounding: the proof may not
  // separate them however many rounds it runs, and so gives up.
  bisim::InvariantModel model;
  model.num_states = 3;
  model.num_actions = 1;
  model.reward = {0, 0, 1};
  model.rounding_depth = 1000;
  model.smallest_term = 0.25;
  model.expectation = [](std::uint32_t s, std::uint32_t /*a*/, const double* x) {
    const double nudge = s == 1 ? 1e-15 : 0;
    return s == 2 ? x[2] : (0.5 + nudge) * x[2];
  };
  EXPECT_FALSE(bisim::prove_discrete(model).discrete);
}

}  // namespace
}  // namespace oasis
