#pragma once
// A grid context's quotient and policy from its rows in product form (continuous_options.hpp,
// GridRows): when the invariants of bisim/discrete_proof.hpp prove that no two cells are
// bisimilar, the quotient is the finite MDP itself (block z = cell z, `outside` last) and
// value iteration runs on the product rows. Otherwise nothing is filled in, and the caller
// materialises the rows for the exact refinement.

#include <string>

#include "geom/grid_geometry.hpp"
#include "geom/grid_product_rows.hpp"
#include "model/model_ir.hpp"
#include "pipeline/continuous_abstraction.hpp"

namespace oasis::pipeline {

// Whether the rows of `rows` should stay in product form under `options`.
bool wants_product_form(const geom::ProductRows& rows, const model::ModelIR& ir,
                        const ContinuousOptions& options);

enum class ProductOutcome {
  kSolved,       // blocks, quotient, policy and values filled in
  kNotDiscrete,  // the proof did not go through: `result` is as it was
  kFailed,       // value iteration did not converge: `error` says so
};

// Fills `result`'s blocks, quotient (its rewards; its rows only with options.keep_rows),
// policy, values and stage seconds, and reports each stage through options.progress.
ProductOutcome solve_in_product_form(const geom::GridGeometry& geometry,
                                     const geom::ProductRows& rows, const model::ModelIR& ir,
                                     const ContinuousOptions& options,
                                     ContinuousAbstraction& result, std::string& error);

}  // namespace oasis::pipeline
