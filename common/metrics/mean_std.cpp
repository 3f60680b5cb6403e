#include "metrics/mean_std.hpp"

#include <cmath>

namespace oasis::metrics {

MeanStd mean_std(const std::vector<double>& values) {
  MeanStd result;
  if (values.empty()) return result;
  const auto n = static_cast<double>(values.size());
  for (double v : values)
    result.mean += v;
  result.mean /= n;
  double squares = 0.0;
  for (double v : values)
    squares += (v - result.mean) * (v - result.mean);
  result.std = std::sqrt(squares / n);
  return result;
}

}  // namespace oasis::metrics
