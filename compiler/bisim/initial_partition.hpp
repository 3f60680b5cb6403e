#pragma once
// The partition refinement starts from: states grouped by their set of enabled actions, their
// rewards R(s, a) for every action and, when labels are respected, their class of labels. It is the
// coarsest partition a bisimulation can refine, and it is stable with respect to the set of all
// states.

#include <cstdint>
#include <optional>
#include <vector>

#include "model/explicit_model.hpp"

namespace oasis::bisim {

struct InitialBlocks {
  std::vector<std::uint32_t> block_of;  // labels 0 .. count-1 in order of first state
  std::uint32_t count = 0;
};

// With `rounding_step` (the user's --epsilon), rewards are compared after rounding to multiples
// of it, like probabilities. `label_class` is empty (labels are not respected) or has one class
// per state (model::label_classes): states of different classes start in different blocks.
InitialBlocks blocks_by_rewards(const model::ExplicitModel& model, std::size_t context,
                                std::optional<double> rounding_step,
                                const std::vector<std::uint32_t>& label_class = {});

}  // namespace oasis::bisim
