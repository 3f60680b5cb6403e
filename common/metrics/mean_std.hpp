#pragma once
// How the paper's tables summarise a statistic over seeds (Table I) or trials (Table II):
// "mean ± std", the std being the *population* standard deviation (divide by the number of
// values, as numpy.std does by default).

#include <vector>

namespace oasis::metrics {

struct MeanStd {
  double mean = 0.0;
  double std = 0.0;  // population standard deviation
};

// {0, 0} for no values.
MeanStd mean_std(const std::vector<double>& values);

}  // namespace oasis::metrics
