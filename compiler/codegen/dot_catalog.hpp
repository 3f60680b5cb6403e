#pragma once
// One abstraction of a catalog as a Graphviz digraph: a box per block with its first
// members, reward and policy action; a point per enabled (block, action), bold for the
// policy's action; edges labelled with probabilities.

#include <string>

#include "model/catalog_data.hpp"

namespace oasis::codegen {

std::string abstraction_dot(const model::CatalogData& catalog, std::size_t abstraction);

}  // namespace oasis::codegen
