#include "verify/verifier.hpp"

#include "verify/bisimulation_check.hpp"
#include "verify/coarsest_check.hpp"
#include "verify/partition_shape.hpp"
#include "verify/unlabelled_check.hpp"

namespace oasis::verify {

VerificationResult verify_partition(const model::ExplicitModel& model, std::size_t context,
                                    const model::Partition& partition,
                                    const std::vector<std::uint32_t>& label_class,
                                    bool unlabelled_choices) {
  VerificationResult result = check_partition_shape(model, partition);
  if (unlabelled_choices) {
    if (result.ok()) result = check_unlabelled_bisimulation(model, context, partition, label_class);
    if (result.ok()) result = check_unlabelled_coarsest(model, context, partition, label_class);
    return result;
  }
  if (result.ok()) result = check_bisimulation(model, context, partition, label_class);
  if (result.ok()) result = check_coarsest(model, context, partition, label_class);
  return result;
}

}  // namespace oasis::verify
