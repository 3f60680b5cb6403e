#include "verify/verifier.hpp"

#include "verify/bisimulation_check.hpp"
#include "verify/coarsest_check.hpp"
#include "verify/partition_shape.hpp"

namespace oasis::verify {

VerificationResult verify_partition(const model::ExplicitModel& model, std::size_t context,
                                    const model::Partition& partition) {
  VerificationResult result = check_partition_shape(model, partition);
  if (result.ok()) result = check_bisimulation(model, context, partition);
  if (result.ok()) result = check_coarsest(model, context, partition);
  return result;
}

}  // namespace oasis::verify
