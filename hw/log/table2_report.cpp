#include "log/table2_report.hpp"

#include <iomanip>
#include <optional>
#include <sstream>
#include <string>

#include "metrics/table_text.hpp"

namespace oasis::hw::log {
namespace {

std::string cell(const std::optional<metrics::MeanStd>& value) {
  if (!value) return "unavailable";
  return metrics::mean_std_text(*value);
}

void print_row(std::ostream& out, const char* name, const std::optional<metrics::MeanStd>& ours,
               const metrics::MeanStd& paper) {
  out << metrics::pad_columns(name, 20) << "| " << metrics::pad_columns(cell(ours), 14) << "| "
      << cell(paper) << '\n';
}

std::string reward_sources(const Table2Summary& summary) {
  if (summary.trials == 0) return "none";
  if (summary.truth_reward_trials == summary.trials) return "truth";
  if (summary.truth_reward_trials == 0) return "observed";
  return "mixed";
}

nlohmann::ordered_json stat_json(const std::optional<metrics::MeanStd>& value) {
  if (!value) return nullptr;
  return {{"mean", value->mean}, {"std", value->std}};
}

}  // namespace

void print_table2(std::ostream& out, const Table2Summary& summary) {
  const PaperTable2& paper = kPaperTable2;
  out << "Table II, continuous-space tracking (Go1 treat): ours = mean ± population std over "
      << summary.trials << " trial(s); 'paper' is the paper's printed row over " << paper.trials
      << " trials (reference, not computed).\n";
  out << metrics::pad_columns("statistic", 20) << "| " << metrics::pad_columns("ours", 14)
      << "| paper\n";
  print_row(out, "accuracy", summary.accuracy, paper.accuracy);
  print_row(out, "average lag (s)", summary.avg_lag_s, paper.avg_lag_s);
  print_row(out, "max. lag (s)", summary.max_lag_s, paper.max_lag_s);
  print_row(out, "normalized reward", summary.normalized_reward, paper.normalized_reward);
  out << "steps: " << summary.steps << "; hand-offs: " << summary.handoffs
      << "; reward: " << reward_sources(summary) << " (truth.reward in "
      << summary.truth_reward_trials << " of " << summary.trials << " trials)\n";
  if (summary.truth_trials < summary.trials)
    out << "accuracy and lags need truth.abstraction on every step: " << summary.truth_trials
        << " of " << summary.trials << " trials have it\n";
}

nlohmann::ordered_json table2_json(const Table2Summary& summary) {
  return {{"trials", summary.trials},
          {"steps", summary.steps},
          {"handoffs", summary.handoffs},
          {"reward_source", reward_sources(summary)},
          {"accuracy", stat_json(summary.accuracy)},
          {"avg_lag_s", stat_json(summary.avg_lag_s)},
          {"max_lag_s", stat_json(summary.max_lag_s)},
          {"normalized_reward", stat_json(summary.normalized_reward)}};
}

}  // namespace oasis::hw::log
