#include "pipeline/compact_row_forms.hpp"

#include "geom/grid_mdp.hpp"

namespace oasis::pipeline {

model::ExplicitModel GridCompactRows::materialise(const std::string& name,
                                                  const std::vector<std::string>& actions,
                                                  const model::Objective& objective) const {
  return geom::grid_finite_mdp(rows_, name, actions, objective);
}

}  // namespace oasis::pipeline
