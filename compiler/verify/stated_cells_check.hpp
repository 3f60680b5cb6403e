#pragma once
// The cells a continuous catalog's JSON states, checked against the partition the runtime
// uses. Each JSON cell carries its polytope as A x <= b (codegen/continuous_json.hpp) for tools
// outside the project, which read those rather than the grid or the BSP: a file whose stated
// cells overlapped, or missed part of the domain, would mislead them while the runtime's view
// passed every other check.
//
// A stated cell must be its runtime cell:
// - every stated constraint is, up to a positive factor, one of the cell's own: a face of its
//   grid box, or a half-space on its BSP path or a face of the domain (so the stated polytope
//   holds the cell), and no constraint has all coefficients zero;
// - grid cells state every face of their box (so the polytope is the box);
// - BSP cells in one and two dimensions: the stated polygon, clipped to the domain, has the
//   cell's area (so it is the cell). In more dimensions random points of the domain are each
//   inside the stated polytope of their own cell and of no other.

#include <vector>

#include "model/model_ir.hpp"
#include "oasis/rt/catalog_view.hpp"
#include "verify/catalog_check.hpp"

namespace oasis::verify {

// One cell as stated: rows[r] . x <= bounds[r] over the abstraction's relevant variables.
struct StatedCell {
  std::vector<std::vector<double>> rows;
  std::vector<double> bounds;
};

// `stated[a]` holds abstraction a's cells in the catalog's order. One check per abstraction.
std::vector<CatalogCheck> check_stated_cells(const model::ModelIR& ir,
                                             const rt::CatalogView& catalog,
                                             const std::vector<std::vector<StatedCell>>& stated);

}  // namespace oasis::verify
