#pragma once
// The verifier's own reading of a reward's guard over the continuous variables, as a
// conjunction of linear inequalities a.x <= b (or < b).
//
// The front end and the geometry layer read guards symbolically (model/affine.hpp). This file
// reads them by evaluation instead: each side of a comparison is evaluated exactly at the
// origin and at the n unit points, which gives its coefficients when it is affine. The two
// readings share only the IR, so that a mistake in one shows up as a disagreement with the
// other rather than in both (docs/geometry.md, "What the verifier shares").

#include <cstddef>
#include <optional>
#include <vector>

#include "model/model_ir.hpp"

namespace oasis::verify {

// nullopt when `guard` is not a conjunction of comparisons between affine sides, region
// references and `true`.
std::optional<std::vector<model::LinearConstraint>> guard_constraints(
    const model::Expression& guard, std::size_t num_variables,
    const std::vector<model::Region>& regions);

}  // namespace oasis::verify
