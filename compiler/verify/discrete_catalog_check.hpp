#pragma once
// The independent check of everything a compiled (discrete) catalog carries, against the
// model it claims to come from: names, the switching model and prior, the observation model
// (the spec's `observation` block, or none), and per abstraction
// the partition (verify_partition: a bisimulation, and the coarsest), the block rewards, the
// quotient's transitions and rewards, the policy (optimal for its quotient within a stated
// tolerance, by policy evaluation written here) and the values, and the robust section's
// full-state transitions. It shares no code with the compiler's quotient, policy or
// emitters: only the model, the runtime's view of the catalog, and exact rationals.
//
// Numbers: a catalog carries the nearest double d to each exact value q; d is accepted when
// |d - q| <= 2^-50 |q| + 2^-60 (a few units of rounding, compared exactly with GMP; sums of
// many rounded terms get their own slack). Policy and values: tol = 1e-6 max(1, max|V|).

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "model/explicit_model.hpp"
#include "oasis/rt/catalog_view.hpp"
#include "verify/catalog_check.hpp"

namespace oasis::verify {

struct CatalogCheckOptions {
  // The catalog was compiled with `--robust P`: its observation model must be the symmetric
  // one with p_correct P instead of the spec's (whose reward source it keeps).
  std::optional<double> robust_p_correct;
};

// One entry per item, in order; every item is checked even after a failure.
std::vector<CatalogCheck> check_discrete_catalog(const model::ExplicitModel& model,
                                                 const rt::CatalogView& catalog,
                                                 const CatalogCheckOptions& options = {});

}  // namespace oasis::verify
