#pragma once
// The finite MDP of a polytope partition, in the shape of geom/grid_mdp.hpp: one state
// per cell (the tree's cell order), then `outside`, absorbing with reward 0; one context;
// exact rows that sum to exactly 1, so the bisimulation engine and value iteration run on it
// unchanged.
//
// The row of cell C under action a is the successor distribution of C's representative x_C
// (geom/polytope_rows.hpp); the rows are found as geom/polytope_walk_rows.hpp keeps them.

#include <string>
#include <vector>

#include "geom/polytope_geometry.hpp"
#include "geom/polytope_partition.hpp"
#include "model/explicit_model.hpp"

namespace oasis::geom {

struct PolytopeMdp {
  model::ExplicitModel mdp;
  Rational epsilon;  // the partition's sound bound, max over cells and actions
  [[nodiscard]] bool exact() const { return sgn(epsilon) == 0; }
};

PolytopeMdp polytope_finite_mdp(const PolytopeGeometry& geometry,
                                const PolytopePartition& partition,
                                const std::vector<std::string>& action_names,
                                const model::Objective& objective);

}  // namespace oasis::geom
