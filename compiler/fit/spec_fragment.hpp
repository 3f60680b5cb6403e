#pragma once
// The spec text the fits print for the user to paste (docs/fitting.md). Probabilities are
// written as decimals with a fixed number of digits; a distribution's row is rounded so that
// its decimals sum to exactly 1 (the spec checks rows exactly), the largest entry taking up
// the rounding.

#include <cstdint>
#include <string>
#include <vector>

namespace oasis::fit {

// `value` with at most `decimals` digits after the point, trailing zeros dropped ("0.8").
// `value` rounded to `decimals` places, trailing zeros dropped ("0.25"). Throws
// std::domain_error for a value that is not finite or too large for 18 digits, rather than
// rounding it into undefined behaviour.
std::string decimal_text(double value, int decimals);

// A probability row as decimals that sum to exactly 1 (entries that round to 0 stay "0").
std::vector<std::string> exact_row(const std::vector<double>& row, int decimals);

// `switching stay p;`
std::string switching_stay_fragment(double p_stay, int decimals = 4);

// `switching { a -> p: a + q: b; ... }`, one row per context (entries that round to 0 left
// out), `matrix` row-major N x N.
std::string switching_matrix_fragment(const std::vector<double>& matrix,
                                      const std::vector<std::string>& contexts, int decimals = 4);

// The observation block: `observation { state noise sigma; reward follows true; }`.
// Throws std::domain_error when sigma, so rounded, is not a state noise the spec language
// takes ([0, 1)): a fragment that `oasisc check` would refuse is never printed.
std::string state_noise_fragment(double sigma, const std::string& reward_follows, int decimals = 4);

// The same with a confusion matrix, one row per true state:
// `observation { state confusion { s1 -> 0.9: s1 + 0.1: s2; ... } reward follows true; }`.
std::string confusion_fragment(const std::vector<double>& matrix,
                               const std::vector<std::string>& states,
                               const std::string& reward_follows, int decimals = 4);

// A continuous observation model's object (docs/spec-language.md):
// `object NAME (x, y) { noise a + b * d + c * d * d; }`, `sigma` being a, b, c (or fewer).
std::string object_noise_fragment(const std::string& name,
                                  const std::vector<std::string>& variables,
                                  const std::vector<double>& sigma, int digits = 4);

// A number with `digits` significant digits, for coefficients ("0.00254", "1.2e-06").
std::string significant_text(double value, int digits = 4);

}  // namespace oasis::fit
