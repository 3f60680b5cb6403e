#pragma once
// What oasis-sim table1 writes: the table in the paper's layout with the paper's published
// numbers beside ours (reference only), the rows as JSON, per-trial CSV traces and SVG plots of
// true vs inferred abstraction (like Fig. 3 of the paper).

#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "metrics/mean_std.hpp"
#include "table1/table1.hpp"

namespace oasis::table1 {

// The paper's Table I, as printed (mean ± std over five seeds). Reference only: nothing here
// is computed from it.
struct PaperReference {
  metrics::MeanStd accuracy;
  metrics::MeanStd avg_lag;
  metrics::MeanStd max_lag;
};

std::optional<PaperReference> paper_reference(const std::string& model, Pattern pattern);

// The table: per transition model, one block with the rows of `filter` (ours) and the paper's
// numbers; then every filter's accuracy and average lag side by side.
void print_table(std::ostream& out, const std::vector<RowResult>& rows,
                 const Table1Options& options);

// [{"model", "pattern", "noise", "filter", "accuracy", "avg_lag", "max_lag",
//   "zero_likelihood_steps"}], each statistic {"mean": x, "std": y}.
nlohmann::json rows_json(const std::vector<RowResult>& rows);

bool write_text(const std::filesystem::path& path, const std::string& text, std::string& error);

// Per-trial trace: t, true context, inferred ML, true state, observed state, reward (names).
std::string trace_csv(const Trace& trace, const std::vector<std::string>& context_names,
                      const std::vector<std::string>& state_names);

// File stem of a trial: model-i_step_none_paper_seed0.
std::string trial_stem(const TrialSpec& spec);

// True context (solid blue) and inferred ML abstraction (dotted orange) over the first
// `steps` steps, hand-written SVG.
std::string trace_svg(const TrialSpec& spec, const Trace& trace,
                      const std::vector<std::string>& context_names, std::size_t steps = 150);

}  // namespace oasis::table1
