#pragma once
// A continuous context's quotient and policy from rows kept compact (continuous_options.hpp,
// GridRows): the grid's rows in product form (geom/grid_product_rows.hpp) or the polytope
// path's rows as walks of its tree (geom/polytope_walk_rows.hpp). When the invariants of
// bisim/discrete_proof.hpp prove that no two cells are bisimilar, the quotient is the finite
// MDP itself (block z = cell z, `outside` last) and value iteration runs on the compact rows.
// Otherwise nothing is filled in, and the caller materialises the rows for the exact
// refinement.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "model/explicit_model.hpp"
#include "model/model_ir.hpp"
#include "pipeline/continuous_abstraction.hpp"
#include "support/rational.hpp"

namespace oasis::pipeline {

// What the proof and the solver ask of compact rows: states are the cells, then `outside`.
class CompactRows {
 public:
  virtual ~CompactRows() = default;
  [[nodiscard]] virtual std::uint32_t num_states() const = 0;
  [[nodiscard]] virtual std::uint32_t num_actions() const = 0;
  [[nodiscard]] virtual ValueId state_reward(std::uint32_t s) const = 0;
  [[nodiscard]] virtual const RationalPool& values() const = 0;
  // Called with x before the expectations of a sweep over x (and again when x changes).
  virtual void prepare(const double* /*x*/) const {}
  // Σ_t P(s, a, t) x[t] in doubles, within the bound rounding_depth() gives.
  [[nodiscard]] virtual double expectation(std::uint32_t s, std::uint32_t a,
                                           const double* x) const = 0;
  [[nodiscard]] virtual std::uint32_t rounding_depth() const = 0;
  [[nodiscard]] virtual double smallest_term() const = 0;
  // The exact rows, for the quotient's rows when they are written.
  [[nodiscard]] virtual model::ExplicitModel materialise(
      const std::string& name, const std::vector<std::string>& actions,
      const model::Objective& objective) const = 0;
};

// Whether rows that would materialise into `edges` edges should stay compact under `options`.
bool wants_product_form(std::size_t edges, const model::ModelIR& ir,
                        const ContinuousOptions& options);

enum class ProductOutcome {
  kSolved,       // blocks, quotient, policy and values filled in
  kNotDiscrete,  // the proof did not go through: `result` is as it was
  kFailed,       // value iteration did not converge: `error` says so
};

// Fills `result`'s blocks, quotient (its rewards; its rows only with options.keep_rows),
// policy, values and stage seconds, and reports each stage through options.progress.
// `form` names the rows' form in the report.
ProductOutcome solve_in_product_form(const CompactRows& rows, const std::string& form,
                                     const model::ModelIR& ir, const ContinuousOptions& options,
                                     ContinuousAbstraction& result, std::string& error);

}  // namespace oasis::pipeline
