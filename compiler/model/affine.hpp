#pragma once
// Reading expressions over continuous variables as affine forms (sum c_i x_i + d) and
// polyhedral conditions (conjunctions of linear inequalities), shared by the front end (region
// and guard checks) and the geometry layer.

#include <optional>
#include <vector>

#include "model/interval.hpp"
#include "model/model_ir.hpp"

namespace oasis::model {

struct AffineForm {
  std::vector<Rational> coefficients;  // one per continuous variable
  Rational constant;
};

// nullopt when `expr` is not affine (a product of variables, a division by a variable, ...).
std::optional<AffineForm> affine_form(const model::Expression& expr, std::size_t num_variables);

// An affine form whose coefficients are known only as intervals: expressions such as
// cos(0.1) * x + sqrt(2), where a function of constants has no exact rational value. Every
// interval is rounded outward (model/interval.hpp). nullopt when `expr` is not affine in the
// continuous variables with constant coefficients (a product of variables, an input, a function
// of a variable, a divisor or function argument whose enclosure is refused).
struct IntervalAffineForm {
  std::vector<Interval> coefficients;  // one per continuous variable
  Interval constant;
};
std::optional<IntervalAffineForm> interval_affine_form(const model::Expression& expr,
                                                       std::size_t num_variables);

// The constraints of a conjunction of linear comparisons and region references; nullopt when
// `expr` is not of that shape (uses '|', '!', '!=', or a non-linear side).
std::optional<std::vector<model::LinearConstraint>> polyhedral_constraints(
    const model::Expression& expr, std::size_t num_variables,
    const std::vector<model::Region>& regions);

}  // namespace oasis::model
