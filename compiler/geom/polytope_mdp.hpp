#pragma once
// The finite MDP of a polytope partition, in the shape of geom/grid_mdp.hpp: one state
// per cell (the tree's cell order), then `outside`, absorbing with reward 0; one context;
// exact rows that sum to exactly 1, so the bisimulation engine and value iteration run on it
// unchanged.
//
// The row of cell C under action a is the successor distribution of C's representative x_C:
// the successor is uniform on the box B = M x_C + t + W (a point on the undisturbed axes),
// and target cell Q gets vol(B ∩ Q) / vol(B), measured in the disturbed coordinates on the
// slice through the fixed undisturbed ones, exact. The mass outside the domain goes to
// `outside`. Candidate targets come from walking the BSP tree with B.

#include <span>
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

// One row alone, exact: (cell, probability) pairs for the cells of `tree` with a positive
// probability, in increasing cell order, and the probability of `outside` last with index
// tree.num_cells() when positive. For checks and for the integrator. `rounded`, when given,
// is tree.rounded_nodes() (made once per tree): it speeds up the walk, not the result.
std::vector<std::pair<std::size_t, Rational>> successor_row(
    const PolytopeGeometry& geometry, const BspTree& tree, const AffineStep& step,
    const Point& from, std::span<const RoundedBspNode> rounded = {});

}  // namespace oasis::geom
