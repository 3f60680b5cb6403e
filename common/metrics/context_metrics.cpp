#include "metrics/context_metrics.hpp"

#include <algorithm>
#include <cassert>

namespace oasis::metrics {

std::vector<std::uint32_t> switch_lags(const std::vector<std::uint32_t>& truth,
                                       const std::vector<std::uint32_t>& inferred) {
  assert(truth.size() == inferred.size());
  std::vector<std::uint32_t> lags;
  const std::size_t steps = truth.size();
  for (std::size_t k = 1; k < steps; ++k) {
    if (truth[k] == truth[k - 1]) continue;
    std::size_t end = k + 1;
    while (end < steps && truth[end] == truth[end - 1])
      ++end;
    std::size_t j = k;
    while (j < end && inferred[j] != truth[j])
      ++j;
    lags.push_back(static_cast<std::uint32_t>(j - k));
  }
  return lags;
}

double accuracy(const std::vector<std::uint32_t>& truth,
                const std::vector<std::uint32_t>& inferred) {
  assert(truth.size() == inferred.size());
  if (truth.empty()) return 0.0;
  std::size_t right = 0;
  for (std::size_t k = 0; k < truth.size(); ++k)
    right += truth[k] == inferred[k] ? 1 : 0;
  return static_cast<double>(right) / static_cast<double>(truth.size());
}

TrialMetrics trial_metrics(const std::vector<std::uint32_t>& truth,
                           const std::vector<std::uint32_t>& inferred) {
  TrialMetrics metrics;
  metrics.accuracy = accuracy(truth, inferred);
  const std::vector<std::uint32_t> lags = switch_lags(truth, inferred);
  metrics.switches = lags.size();
  if (lags.empty()) return metrics;
  double sum = 0.0;
  for (std::uint32_t lag : lags)
    sum += lag;
  metrics.avg_lag = sum / static_cast<double>(lags.size());
  metrics.max_lag = *std::max_element(lags.begin(), lags.end());
  return metrics;
}

}  // namespace oasis::metrics
