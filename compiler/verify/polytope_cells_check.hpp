#pragma once
// The independent check of a continuous abstraction whose cells are convex polytopes (the
// compiler's polytope path: a BSP in the catalog, runtime/include/oasis/rt/bsp_locator.hpp),
// from the catalog's numbers and the spec alone. Shares no code with compiler/geom.
//
// Every cell is the domain box cut by the half-spaces on its path from the root. In one and
// two dimensions each cell is clipped out of the domain as an interval or a polygon (in
// doubles): every cell non-empty, their areas summing to the domain's, the reward constant
// on every cell (each reward condition's linear forms compared at the cell's corners) and
// equal to its block's, and, with the transition rows in the file, each sampled cell's row
// recomputed from the spec at points next to its corners and at its centroid (the area of
// the successor box clipped to each cell) and compared with the catalog's row in total
// variation. In more dimensions the reward is compared at random points of every cell. In
// all dimensions: the runtime's locator against plain membership (the point satisfies its
// cell's path and no other cell's) on random points.

#include <cstdint>
#include <optional>
#include <string>

#include "model/model_ir.hpp"
#include "oasis/rt/catalog_view.hpp"

namespace oasis::verify {

struct PolytopeCellsVerdict {
  std::optional<std::string> problem;  // the first failure, if any
  std::string summary;                 // what was checked, for the report
};

// `with_rows`: the abstraction carries its quotient's rows (compile --with-transitions).
PolytopeCellsVerdict check_polytope_cells(const model::ModelIR& ir, std::size_t context,
                                          const rt::AbstractionView& abs, std::uint32_t actions,
                                          bool with_rows);

}  // namespace oasis::verify
