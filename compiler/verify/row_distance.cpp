#include "verify/row_distance.hpp"

#include <cmath>

#include "verify/number_text.hpp"

namespace oasis::verify {

double total_variation(const std::vector<double>& difference) {
  double sum = 0;
  for (const double d : difference)
    sum += std::fabs(d);
  return sum / 2;
}

std::string row_too_far(std::uint64_t cell, const std::string& action, double variation,
                        double epsilon) {
  return "cell " + std::to_string(cell) + " under " + action +
         ": from one of its points the successor distribution differs from the catalog's row "
         "by " +
         number_text(variation) + " in total variation, more than epsilon " + number_text(epsilon);
}

}  // namespace oasis::verify
