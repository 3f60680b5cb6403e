#pragma once
// The JSON carrier of a continuous model compiled with an objective: the grid, the finite
// actions, the controller and the lower and upper bounds per cell (docs/guarantees.md, "The
// output"). `oasisc verify` and the Monte-Carlo check read it back.

#include "codegen/json_writer.hpp"
#include "model/model_ir.hpp"
#include "pipeline/guarantee_compile.hpp"

namespace oasis::codegen {

// Written in pieces: a large grid's arrays never exist whole as a tree.
void write_controller_json(JsonWriter& out, const model::ModelIR& ir,
                           const pipeline::GuaranteeResult& result);

}  // namespace oasis::codegen
