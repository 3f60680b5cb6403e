#pragma once
// What `oasis-go1 score` prints: Table II with our numbers beside the paper's printed row
// (reference only: nothing is computed from it), and the same numbers as JSON.

#include <cstddef>
#include <ostream>

#include <nlohmann/json.hpp>

#include "log/table2_metrics.hpp"
#include "metrics/mean_std.hpp"

namespace oasis::hw::log {

// The paper's Table II as printed: mean ± std over 12 trials, lags in seconds at 0.2 s a step.
struct PaperTable2 {
  metrics::MeanStd accuracy;
  metrics::MeanStd avg_lag_s;
  metrics::MeanStd max_lag_s;
  metrics::MeanStd normalized_reward;
  std::size_t trials = 0;
  double period_s = 0.0;
};

inline constexpr PaperTable2 kPaperTable2{{0.91, 0.07}, {0.37, 0.24}, {2.31, 1.48},
                                          {0.27, 0.11}, 12,           0.2};

// A header line, one line per statistic (ours | paper), then the counts behind ours and, when
// a statistic is unavailable, why.
void print_table2(std::ostream& out, const Table2Summary& summary);

// {"trials": N, "steps": S, "handoffs": H, "reward_source": "truth" | "observed" | "mixed" |
// "none",
//  "accuracy": {"mean": x, "std": y}, "avg_lag_s": ..., "max_lag_s": ...,
//  "normalized_reward": ...}; an unavailable statistic is null.
nlohmann::ordered_json table2_json(const Table2Summary& summary);

}  // namespace oasis::hw::log
