#pragma once
// Reading expressions over continuous variables as affine forms (sum c_i x_i + d) and
// polyhedral conditions (conjunctions of linear inequalities), shared by the front end (region
// and guard checks) and the geometry layer.

#include <optional>
#include <vector>

#include "model/model_ir.hpp"

namespace oasis::model {

struct AffineForm {
  std::vector<Rational> coefficients;  // one per continuous variable
  Rational constant;
};

// nullopt when `expr` is not affine (a product of variables, a division by a variable, ...).
std::optional<AffineForm> affine_form(const model::Expression& expr, std::size_t num_variables);

// The constraints of a conjunction of linear comparisons and region references; nullopt when
// `expr` is not of that shape (uses '|', '!', '!=', or a non-linear side).
std::optional<std::vector<model::LinearConstraint>> polyhedral_constraints(
    const model::Expression& expr, std::size_t num_variables,
    const std::vector<model::Region>& regions);

}  // namespace oasis::model
