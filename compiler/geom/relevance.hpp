#pragma once
// Attention by exact projection: which continuous variables a context needs.
//
// A variable is relevant to a context when the context's reward conditions read it, or when
// the dynamics of a relevant variable read it under some action: the smallest set closed
// under both rules. docs/geometry.md proves that, when
//   (1) every reward of the context is a constant on a polyhedral condition,
//   (2) every disturbance is additive, independent of the state, and independent across
//       variables, and
//   (3) leaving the domain is judged on the relevant variables only (the `outside` cell),
// two states that agree on the relevant variables are bisimilar: the relevant variables'
// next values depend only on the relevant variables and on their own disturbances, and the
// reward only on them. The abstraction can then be computed on the relevant subspace alone.
// The analysis checks (1) and (2) on the model and names any condition that fails.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "model/model_ir.hpp"

namespace oasis::geom {

struct Relevance {
  std::vector<std::uint32_t> relevant;  // indices into ModelIR::continuous, in order
  std::vector<std::uint32_t> ignored;   // the others, in order
  // Per relevant variable (same order): why it is relevant, e.g. "a reward condition" or
  // "the dynamics of x1 under 'left'".
  std::vector<std::string> reasons;
  // The conditions of exact projection that fail, as sentences; empty when the projection
  // onto `relevant` is an exact bisimulation.
  std::vector<std::string> failed_conditions;

  [[nodiscard]] bool exact() const { return failed_conditions.empty(); }
};

// x' = matrix x + offset restricted to the relevant axes (rows and columns in relevance order):
// what both geometry paths start from (the disturbances are read per path).
struct ProjectedStep {
  std::vector<std::vector<Rational>> matrix;
  std::vector<Rational> offset;
};
ProjectedStep project_step(const model::AffineDynamics& affine, const Relevance& relevance);

// The relevance of the continuous variables to context `context` of a continuous model.
Relevance analyse_relevance(const model::ModelIR& ir, std::size_t context);

// Every variable of the model as relevant: the no-attention baseline.
Relevance full_state(const model::ModelIR& ir);

}  // namespace oasis::geom
