#pragma once
// A picture of one continuous abstraction (`oasisc compile --format svg`), so that a person
// sees the attention at a glance: the cells of the grid over the first two relevant
// variables, filled with the colour of the policy's action in their block and darker where
// the block's value is higher; thin lines between cells of different blocks, thick lines
// where the reward changes (the reward regions' outlines), and a caption with the relevant
// variables, epsilon and the counts. A 1-D abstraction is drawn as a strip; with more than
// two relevant variables the picture is the 2-D slice through the centre of the others.

#include <string>

#include "pipeline/continuous_catalog.hpp"

namespace oasis::codegen {

std::string abstraction_svg(const pipeline::ContinuousCatalog& catalog, std::size_t abstraction);

}  // namespace oasis::codegen
