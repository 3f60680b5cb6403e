#pragma once
// The JSON of a continuous catalog, for people and for tools outside the project (keep the
// names: they are a contract, docs/geometry.md). Top level: format, name, spec_hash,
// compiler_version, variables, actions, switching, prior, abstractions. Each abstraction:
//   context, relevant_variables (names), epsilon (the sound bound), exact (bool),
//   num_blocks, outside_block, grid (per relevant variable its breakpoints),
//   cells: [{"A": [[...]], "b": [...], "block": z}]  meaning A x <= b over the relevant
//          variables in the listed order (a grid cell is a box: two rows per variable;
//          a polytope cell has its irredundant constraints),
//   bsp (polytope cells only; the grid is then the domain box): {"normal": [[a...] or []],
//          "bound": [c], "below": [n], "above": [n], "cell": [leaf's cell or null]}, one
//          entry per node, root first, a point with a.x <= c going `below`,
//   blocks: [{"reward": r, "policy": "action", "value": v, "next": {...}}]
// where `next` (only with transitions) maps each action name to [[block, probability], ...]
// with zero entries omitted. Written compactly (no indentation) and streamed: it can be large (327
// MB for the Go1 catalog with transitions).

#include <string>

#include "codegen/json_writer.hpp"
#include "pipeline/continuous_catalog.hpp"

namespace oasis::codegen {

// Streams the document into `out` (the caller ends it with out.finish()).
void write_continuous_catalog_json(JsonWriter& out, const pipeline::ContinuousCatalog& catalog,
                                   bool with_transitions);
// The whole document as text (small catalogs and tests).
std::string continuous_catalog_json(const pipeline::ContinuousCatalog& catalog,
                                    bool with_transitions);

}  // namespace oasis::codegen
