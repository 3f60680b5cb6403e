#pragma once
// What `oasisc quotient` prints and writes: the summary table, the JSON document, DOT.

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "input/model_loader.hpp"
#include "pipeline/discrete_catalog.hpp"

namespace oasis::cli {

void print_summary(std::ostream& out, const model::ExplicitModel& model,
                   const std::vector<pipeline::DiscreteAbstraction>& results, double load_seconds,
                   double peak_mib, std::optional<double> rounding_step);

// Keys: file, model, exact, epsilon (the rounding step; null when exact), load_seconds,
// peak_memory_mib, contexts[] with name, states, transitions, blocks, seconds, splitters,
// edge_visits (and partition when asked: blocks as lists of state names, or of indices for unnamed
// imported states).
nlohmann::json quotient_json(const input::LoadedModel& loaded,
                             const std::vector<pipeline::DiscreteAbstraction>& results,
                             double load_seconds, double peak_mib, bool with_partition,
                             std::optional<double> rounding_step);

// Graphviz: a node per block (its first members and rewards), a point per enabled
// (block, action) and edges labelled with exact probabilities.
std::string quotient_dot(const model::ExplicitModel& model,
                         const pipeline::DiscreteAbstraction& result,
                         const model::ExplicitModel& quotient);

// `output` itself, or with ".CONTEXT" inserted before the extension when several contexts
// go to separate files.
std::string output_path(const std::string& output, const std::string& format,
                        const std::string& context, bool per_context);

}  // namespace oasis::cli
