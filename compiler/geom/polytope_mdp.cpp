#include "geom/polytope_mdp.hpp"

#include "geom/polytope_error_bound.hpp"
#include "geom/polytope_walk_rows.hpp"

namespace oasis::geom {

PolytopeMdp polytope_finite_mdp(const PolytopeGeometry& geometry,
                                const PolytopePartition& partition,
                                const std::vector<std::string>& action_names,
                                const model::Objective& objective) {
  PolytopeMdp result;
  result.mdp =
      PolytopeWalkRows(geometry, partition).materialise(geometry.context, action_names, objective);
  result.epsilon = partition_error_bound(geometry, partition.tree);
  return result;
}

}  // namespace oasis::geom
