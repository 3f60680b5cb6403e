#pragma once
// A continuous model with an objective (docs/guarantees.md), compiled: its interval MDP on the
// spec's grid and the controller synthesised on it, with the bounds and what they cost. Only
// plain values leave this file: the emitters (codegen/controller_json.hpp) read these.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "guarantee/interval_mdp.hpp"
#include "guarantee/synthesis.hpp"
#include "model/model_ir.hpp"

namespace oasis::pipeline {

struct GuaranteeOptions {
  unsigned jobs = 1;
  // Bytes the interval MDP may take (0: no limit): past it the compile stops before building
  // the rows (std::length_error), from an estimate on a sample of cells.
  std::uint64_t memory_budget = 0;
  guarantee::SynthesisOptions synthesis;
  // Stage lines ("abstraction: 2500 cells x 10 actions (0.41 s)"), when wanted.
  std::function<void(const std::string&)> progress;
};

struct GuaranteeResult {
  guarantee::UniformGrid grid;
  std::vector<guarantee::ActionChoice> actions;
  guarantee::Synthesis synthesis;
  std::uint64_t entries = 0;  // interval entries of the abstraction's factored rows
  std::uint64_t bytes = 0;    // what the rows took
  // Classes of cells with equal rows for every action (guarantee/row_classes.hpp).
  std::uint64_t distinct_rows = 0;
  double abstraction_seconds = 0;
  double synthesis_seconds = 0;
};

// Throws model::EnclosureError when the map cannot be enclosed on some cell (a divisor that
// reaches 0 there, ...), std::length_error past the memory budget, std::invalid_argument for
// a grid doubles cannot hold.
GuaranteeResult compile_guarantee(const model::ModelIR& ir, const GuaranteeOptions& options);

// "x1 in [-5, -4.8), x2 in [...]": a cell as people read it.
std::string describe_cell(const guarantee::UniformGrid& grid, const model::ModelIR& ir,
                          std::size_t cell);

}  // namespace oasis::pipeline
