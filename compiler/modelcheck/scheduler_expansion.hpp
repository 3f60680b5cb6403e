#pragma once
// From a policy of the reduced system to a memoryless scheduler of the model. A variable of one
// state takes its policy's action. A collapsed end component takes its policy's choice in the
// one state that owns it, and everywhere else a choice inside the component that moves
// towards that state (an attractor over the component's own choices): staying inside the
// component keeps the value but never reaches anything, so the scheduler must head for the
// exit. States of known value take their precomputation witness, or kAnyAction.

#include <cstdint>
#include <vector>

#include "modelcheck/reduced_system.hpp"

namespace oasis::modelcheck {

Scheduler expand_policy(const ChoiceGraph& graph, const ReducedSystem& system,
                        const std::vector<std::uint32_t>& policy,
                        const std::vector<ChoiceId>& witness, const std::vector<bool>& internal);

}  // namespace oasis::modelcheck
