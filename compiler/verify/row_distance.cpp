#include "verify/row_distance.hpp"

#include <cmath>
#include <cstdio>

namespace oasis::verify {

double total_variation(const std::vector<double>& difference) {
  double sum = 0;
  for (const double d : difference)
    sum += std::fabs(d);
  return sum / 2;
}

std::string row_too_far(std::uint64_t cell, const std::string& action, double variation,
                        double epsilon) {
  char numbers[96];
  std::snprintf(numbers, sizeof numbers, "%.10g in total variation, more than epsilon %.10g",
                variation, epsilon);
  return "cell " + std::to_string(cell) + " under " + action +
         ": from one of its points the successor distribution differs from the catalog's row "
         "by " +
         numbers;
}

}  // namespace oasis::verify
