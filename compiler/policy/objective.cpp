#include "policy/objective.hpp"

#include <stdexcept>
#include <string>

namespace oasis::policy {

ResolvedObjective resolve_objective(const model::ExplicitModel& model,
                                    const PolicyOptions& options) {
  return resolve_objective(model.objective, options);
}

ResolvedObjective resolve_objective(const model::Objective& stated, const PolicyOptions& options) {
  if (!(options.tolerance > 0)) throw std::invalid_argument("the tolerance must be positive");
  ResolvedObjective objective;
  if (options.discount || options.horizon) {
    objective.horizon = options.horizon;
    // A finite horizon without a discount sums the rewards of its steps undiscounted.
    objective.discount = options.discount.value_or(options.horizon ? 1.0 : kDefaultDiscount);
  } else if (stated.discount || stated.horizon) {
    objective.horizon = stated.horizon;
    objective.discount = stated.discount ? to_double(*stated.discount) : 1.0;
  } else {
    objective.default_discount = true;
  }
  if (!(objective.discount > 0 && objective.discount <= 1)) {
    throw std::invalid_argument("the discount must be in (0, 1], not " +
                                std::to_string(objective.discount));
  }
  if (objective.horizon && *objective.horizon == 0) {
    throw std::invalid_argument("the horizon must be at least 1 step");
  }
  if (!objective.horizon && objective.discount == 1) {
    throw std::invalid_argument(
        "discount 1 needs a finite horizon: undiscounted values over an infinite horizon may "
        "be infinite");
  }
  return objective;
}

double stopping_threshold(const ResolvedObjective& objective, double tolerance) {
  return tolerance * (1 - objective.discount) / (2 * objective.discount);
}

}  // namespace oasis::policy
