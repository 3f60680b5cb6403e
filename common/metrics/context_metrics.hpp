#pragma once
// The per-trial statistics of the paper's tables, computed from a trial's true and inferred
// (ML) contexts, one entry per step. The paper defines them in words (Sec. IV, footnotes on
// accuracy and lag); this is the one reading of those words that Table I (tools/table1) and
// Table II (hw/log) share.
//
//  * accuracy: the fraction of steps k at which inferred[k] == truth[k].
//  * switch:   a step k >= 1 with truth[k] != truth[k-1]. Its segment runs from k up to (not
//              including) the next switch, or to the end of the trial.
//  * lag of a switch at k: the number of steps from k until the first step j of its segment
//              with inferred[j] == truth[j], i.e. j - k: 0 if the filter is right at the switch
//              step itself; the segment's length if it is never right within the segment.
//  * avg lag:  the mean of the lags of the trial's switches; max lag: their maximum. Both are 0
//              for a trial without switches.
// Lags are in steps; a caller that reports seconds multiplies by its step period.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace oasis::metrics {

struct TrialMetrics {
  double accuracy = 0.0;
  double avg_lag = 0.0;  // steps
  double max_lag = 0.0;  // steps
  std::size_t switches = 0;
};

// The lag of every switch in `truth`, in order. truth and inferred have equal length.
std::vector<std::uint32_t> switch_lags(const std::vector<std::uint32_t>& truth,
                                       const std::vector<std::uint32_t>& inferred);

// 0 for an empty trial. truth and inferred have equal length.
double accuracy(const std::vector<std::uint32_t>& truth,
                const std::vector<std::uint32_t>& inferred);

TrialMetrics trial_metrics(const std::vector<std::uint32_t>& truth,
                           const std::vector<std::uint32_t>& inferred);

}  // namespace oasis::metrics
