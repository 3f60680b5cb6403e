#pragma once
// The independent check of a bisimulation result: is `partition` exactly the coarsest
// bisimulation of one context of `model`? Used by `oasisc verify` and by the tests of the
// bisimulation engine, and written to share nothing with it but the model and Partition.

#include <cstddef>

#include "model/explicit_model.hpp"
#include "model/partition.hpp"
#include "verify/violation.hpp"

namespace oasis::verify {

// Runs check_partition_shape, check_bisimulation and check_coarsest in turn and returns the
// first violation, if any. Exact throughout: probabilities and rewards are compared as GMP
// rationals.
// `label_class`: empty, or the states' classes of respected labels (model::label_classes),
// which no block may mix.
// `unlabelled_choices`: Storm's MDP semantics (unlabelled_check.hpp) instead of Definition 1.
VerificationResult verify_partition(const model::ExplicitModel& model, std::size_t context,
                                    const model::Partition& partition,
                                    const std::vector<std::uint32_t>& label_class = {},
                                    bool unlabelled_choices = false);

}  // namespace oasis::verify
