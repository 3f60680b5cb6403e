#pragma once
// `oasisc verify SPEC NAME.controller.json`: an independent check of a controller and its
// bounds (docs/guarantees.md). Two parts, each item a line of verify's report:
//
//  1. Structure, exactly: the model's name and variables; the grid's breakpoints, each the
//     nearest double to low + k (high - low) / cells computed exactly; the inputs and the
//     actions (every declared action with dynamics times every combination of the inputs'
//     values, the last input fastest); the objective; one lower and upper bound per cell with
//     0 <= lower <= upper <= 1; the controller's shape and action indices.
//  2. Monte-Carlo: K cells (a third among cells whose lower bound exceeds 0.05, a third among
//     those whose upper bound is below 0.95, the rest any cell; all of them when there are no
//     more than K), one uniformly random point in each, M runs of the true system from it
//     under the controller (controller_simulation.hpp). With probability at least 1 - delta
//     every cell's estimate p of its success probability is within Hoeffding's margin
//     t = sqrt(ln(2K / delta) / (2M)) of the truth (a union bound over the K cells); the
//     check asks lower - t <= p <= upper + t of each cell. A sound file fails it with
//     probability at most delta.
//
// The simulation runs when the file's shape allows it (its grid, actions, objective and
// controller agree with the spec in number and kind), even if some of its doubles differ from
// the spec's: it uses the file's breakpoints (the controller's own cells) and the spec's input
// values. Runs that leave the grid's box while in the safe set count as failures (the
// pessimistic reading), and unbounded runs still undecided after the step cap too; both are
// counted in the report. Everything is the verifier's own: it reads the model IR and nothing
// else of the compiler.

#include <cstdint>
#include <vector>

#include "model/model_ir.hpp"
#include "verify/catalog_check.hpp"
#include "verify/controller_reader.hpp"

namespace oasis::verify {

struct MonteCarloSettings {
  std::uint64_t samples = 2000;    // M: runs per cell
  std::uint64_t cells = 40;        // K: cells tested
  double confidence = 0.999;       // 1 - delta
  std::uint64_t seed = 1;          // the cells, their points and every run follow from it
  std::uint64_t max_steps = 5000;  // H: unbounded objectives' cap
};

// Hoeffding's margin for `cells` estimates of `samples` runs each at `confidence` jointly.
double hoeffding_margin(std::uint64_t cells, std::uint64_t samples, double confidence);

// The cells the Monte-Carlo part tests, in increasing order (see above).
std::vector<std::size_t> cells_to_test(const std::vector<double>& lower,
                                       const std::vector<double>& upper, std::uint64_t count,
                                       std::uint64_t seed);

// Every check, in the order above; the last item is the Monte-Carlo summary, preceded by a
// line per cell outside its bounds.
std::vector<CatalogCheck> check_controller(const model::ModelIR& ir, const ControllerFile& file,
                                           const MonteCarloSettings& settings);

}  // namespace oasis::verify
