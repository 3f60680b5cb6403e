#include "pipeline/continuous_options.hpp"

namespace oasis::pipeline {

ContinuousTarget continuous_target(const model::ModelIR& spec, const TargetFlags& flags) {
  ContinuousTarget target;
  if (flags.epsilon) {
    target.epsilon = *flags.epsilon;
  } else if (spec.epsilon) {
    target.epsilon = to_double(*spec.epsilon);
  }
  std::optional<std::size_t> budget = flags.max_cells;
  if (!budget && spec.max_cells) budget = static_cast<std::size_t>(*spec.max_cells);
  if (budget) {
    target.grid_cells = *budget;
    target.polytope_cells = *budget;
  }
  return target;
}

}  // namespace oasis::pipeline
