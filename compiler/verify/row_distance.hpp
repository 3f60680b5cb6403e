#pragma once
// The comparison every continuous check makes: a successor distribution recomputed from the
// spec against the catalog's row of the same block, in total variation, and the sentence
// that reports a row farther than the catalog's epsilon.

#include <cstdint>
#include <string>
#include <vector>

namespace oasis::verify {

// Half the L1 norm of `difference` (a distribution minus another over the same blocks).
double total_variation(const std::vector<double>& difference);

std::string row_too_far(std::uint64_t cell, const std::string& action, double variation,
                        double epsilon);

}  // namespace oasis::verify
