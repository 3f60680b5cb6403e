#include "pipeline/compact_row_forms.hpp"

#include "geom/grid_mdp.hpp"

namespace oasis::pipeline {

model::ExplicitModel materialise(const geom::ProductRows& rows, const std::string& name,
                                 const std::vector<std::string>& actions,
                                 const model::Objective& objective) {
  return geom::grid_finite_mdp(rows, name, actions, objective);
}

model::ExplicitModel materialise(const geom::PolytopeWalkRows& rows, const std::string& name,
                                 const std::vector<std::string>& actions,
                                 const model::Objective& objective) {
  return rows.materialise(name, actions, objective);
}

}  // namespace oasis::pipeline
