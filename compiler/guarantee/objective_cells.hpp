#pragma once
// Which cells of the grid are in the objective's sets, read soundly for each bound
// (docs/guarantees.md, "Cells and sets"): the lower bound counts a cell as in the target only
// when all of it is, and as safe only when all of it is; the upper bound counts a cell as in
// the target when some of it may be, and as unsafe only when none of it is safe.

#include <cstdint>
#include <vector>

#include "guarantee/interval_mdp.hpp"
#include "model/model_ir.hpp"

namespace oasis::guarantee {

struct ObjectiveCells {
  // Per cell, 1 or 0.
  std::vector<std::uint8_t> target_lower;  // all of the cell is in T
  std::vector<std::uint8_t> target_upper;  // some of the cell may be in T
  std::vector<std::uint8_t> safe_lower;    // all of the cell is in S
  std::vector<std::uint8_t> safe_upper;    // some of the cell may be in S
  // Whether a successor outside the grid's box could still count as a success (S or T not
  // provably inside the box): the upper bound then values `outside` at 1, else at 0.
  bool outside_may_succeed = true;
};

ObjectiveCells objective_cells(const model::GuaranteeObjective& objective, const model::ModelIR& ir,
                               const UniformGrid& grid);

}  // namespace oasis::guarantee
