#pragma once
// The statistics of Table I, computed from a trial's true and inferred (ML) contexts.
//
//  * accuracy: the fraction of steps k at which inferred[k] == truth[k].
//  * switch:   a step k >= 1 with truth[k] != truth[k-1]. Its segment runs from k up to (not
//              including) the next switch, or to the end of the trial.
//  * lag of a switch at k: the number of steps from k until the first step j of its segment
//              with inferred[j] == truth[j], i.e. j - k: 0 if the filter is right at the switch
//              step itself; the segment's length if it is never right within the segment.
//  * avg lag:  the mean of the lags of the trial's switches; max lag: their maximum. Both are 0
//              for a trial without switches.
// Over seeds, every statistic is summarised as mean and *population* standard deviation
// (divide by the number of seeds, as numpy.std does by default).

#include <cstddef>
#include <cstdint>
#include <vector>

namespace oasis::sim {

struct TrialMetrics {
  double accuracy = 0.0;
  double avg_lag = 0.0;
  double max_lag = 0.0;
  std::size_t switches = 0;
};

// The lag of every switch in `truth`, in order. truth and inferred have equal length.
std::vector<std::uint32_t> switch_lags(const std::vector<std::uint32_t>& truth,
                                       const std::vector<std::uint32_t>& inferred);

double accuracy(const std::vector<std::uint32_t>& truth,
                const std::vector<std::uint32_t>& inferred);

TrialMetrics trial_metrics(const std::vector<std::uint32_t>& truth,
                           const std::vector<std::uint32_t>& inferred);

struct MeanStd {
  double mean = 0.0;
  double std = 0.0;  // population standard deviation
};

MeanStd mean_std(const std::vector<double>& values);

}  // namespace oasis::sim
