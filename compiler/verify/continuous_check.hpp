#pragma once
// The independent check of a continuous catalog against its spec (docs/geometry.md): names,
// switching and prior; per abstraction the variables it attends to (recomputed here), the
// grid's domain, the reward constant on every cell and equal to its block's, and the
// runtime's point location against plain membership; with the transition rows in the file
// (`compile --with-transitions`), every sampled cell's row recomputed from the spec at the
// cell's centre and at points a hair inside its vertices (uniform and point axes exactly up to
// rounding, Gaussian axes with this file's own normal CDF) and compared with the catalog's row
// in total variation (at most the catalog's epsilon), and the policy and values by policy
// evaluation (verify/policy_check.hpp). Shares no code with compiler/geom or compiler/pipeline.

#include <vector>

#include "model/model_ir.hpp"
#include "oasis/rt/catalog_view.hpp"
#include "verify/catalog_check.hpp"

namespace oasis::verify {

std::vector<CatalogCheck> check_continuous_catalog(const model::ModelIR& ir,
                                                   const rt::CatalogView& catalog);

}  // namespace oasis::verify
