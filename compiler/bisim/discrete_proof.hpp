#pragma once
// A proof that the coarsest bisimulation of an MDP is the discrete partition (no two states
// bisimilar), in floating point with every rounding bounded, for models whose rows are too
// many to materialise for partition refinement (geom/grid_product_rows.hpp).
//
// The invariants: h_0(s) = r(s), h_{k+1}(s) = r(s) + Σ_a c_a Σ_t P(s, a, t) h_k(t), with
// r(s) = R(s) - min R and fixed weights c_a > 0. Bisimilar states have equal R and, for every
// action and block, equal probabilities into the block, so by induction on k they have equal
// h_k: two states whose h_k differ are not bisimilar. Every quantity is non-negative, so each
// computed h_k is within a relative error ρ_k of the exact one, ρ_k growing with k from the
// rounding depth the caller states; states whose computed values are further apart than that
// are proven different. Round after round the states are split into groups no invariant tells
// apart yet; when every group has one state, the proof is done.
//
// The proof is sound, not complete: it gives up (false) after `max_stalled_rounds` rounds
// without a split, or when a value gets too small for relative bounds, and the caller then
// runs the exact partition refinement. Exactly bisimilar states always end in one group.

#include <cstdint>
#include <functional>
#include <vector>

namespace oasis::bisim {

struct InvariantModel {
  std::uint32_t num_states = 0;
  std::uint32_t num_actions = 0;
  std::vector<double> reward;  // [state] R(s), rounded the same way for equal rewards
  // Optional: called with x before the expectations of a round over x.
  std::function<void(const double* x)> prepare;
  // Σ_t P(s, a, t) x[t] for non-negative x, with at most `rounding_depth` roundings along
  // any term's path, no term smaller than `smallest_term` times its x, and exact zeros kept.
  std::function<double(std::uint32_t s, std::uint32_t a, const double* x)> expectation;
  std::uint32_t rounding_depth = 0;
  double smallest_term = 0;
};

struct DiscreteProofOptions {
  std::uint32_t max_rounds = 4096;
  std::uint32_t max_stalled_rounds = 32;
};

struct DiscreteProof {
  bool discrete = false;     // proven: every state is its own block
  std::uint32_t rounds = 0;  // invariants computed
  std::uint32_t groups = 0;  // groups of states told apart when it stopped
};

DiscreteProof prove_discrete(const InvariantModel& model, const DiscreteProofOptions& options = {});

}  // namespace oasis::bisim
