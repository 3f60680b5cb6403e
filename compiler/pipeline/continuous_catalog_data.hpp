#pragma once
// A continuous catalog in the runtime's schema (model::CatalogData, read through rt::CatalogView):
// per abstraction its grid over the relevant variables, the block of every cell, the outside
// block, the error bound, block rewards, R^Z, the policy and values; the quotient's
// transition rows only on request (an analysis product the robot does not need).

#include "model/catalog_data.hpp"
#include "pipeline/continuous_catalog.hpp"

namespace oasis::pipeline {

model::CatalogData continuous_catalog_data(const pipeline::ContinuousCatalog& catalog,
                                           bool with_transitions);

// The nearest double at or above an exact bound, so that a bound is never understated.
double bound_as_double(const Rational& bound);

}  // namespace oasis::pipeline
