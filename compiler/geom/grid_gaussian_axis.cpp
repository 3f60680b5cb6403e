#include "geom/grid_gaussian_axis.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace oasis::geom {
namespace {

constexpr int kQuantumBits = 48;  // probabilities are multiples of 2^-48

// The constants of the tolerance (grid_gaussian_axis.hpp says where each comes from): the error of
// one tail evaluation, 1e-14, and a bound on the truncated mass, 1e-12 > P(|Z| >= 7.2).
Rational tail_error() {
  return Rational(1, 100'000'000'000'000L);
}

Rational truncated_mass() {
  return Rational(1, 1'000'000'000'000L);
}

Rational power_of_two(int exponent) {
  return Rational(mpz_class(1) << exponent);
}

// P(Z >= z) and P(Z <= z) for a standard normal Z.
double upper_tail(double z) {
  return 0.5 * std::erfc(z / std::numbers::sqrt2);
}
double lower_tail(double z) {
  return 0.5 * std::erfc(-z / std::numbers::sqrt2);
}

// P(low <= Z < high), from the tails that are small there: subtracting two values near 1
// would lose the digits of a small probability.
double standard_probability(double low, double high) {
  if (low >= 0) return upper_tail(low) - upper_tail(high);
  if (high <= 0) return lower_tail(high) - lower_tail(low);
  return 1 - lower_tail(low) - upper_tail(high);
}

// `p` clamped to [0, 1] and rounded to the nearest multiple of 2^-kQuantumBits, exactly: short
// denominators keep the products of a row's axes small, and equal doubles give equal rows.
Rational quantized(double p) {
  const double scaled = std::nearbyint(std::ldexp(std::clamp(p, 0.0, 1.0), kQuantumBits));
  Rational value(mpz_class(static_cast<long>(scaled)), mpz_class(1) << kQuantumBits);
  value.canonicalize();
  return value;
}

// Rounding may push the sum of the entries past 1 (when hardly any mass leaves the domain):
// take the excess from the largest entries, so the rest of the mass stays non-negative.
void remove_excess(std::vector<std::pair<std::uint32_t, Rational>>& entries, Rational excess) {
  while (sgn(excess) > 0) {
    auto largest =
        std::max_element(entries.begin(), entries.end(),
                         [](const auto& a, const auto& b) { return a.second < b.second; });
    const Rational taken = std::min(largest->second, excess);
    largest->second -= taken;
    excess -= taken;
  }
  std::erase_if(entries, [](const auto& entry) { return sgn(entry.second) == 0; });
}

}  // namespace

Rational truncation_deviations() {
  return Rational(36, 5);
}

Rational sqrt_two_pi_below() {
  return Rational(626'657, 250'000);
}  // 2.506628

std::vector<std::pair<std::uint32_t, Rational>> gaussian_interval_probabilities(
    const Rational& mean, const Rational& deviation, const std::vector<Rational>& breaks) {
  const Rational reach = deviation * truncation_deviations();
  const Rational low = mean - reach;
  const Rational high = mean + reach;
  // The first interval whose upper end is above `low`.
  auto k = static_cast<std::size_t>(std::upper_bound(breaks.begin(), breaks.end(), low) -
                                    breaks.begin());
  k = k == 0 ? 0 : k - 1;
  std::vector<std::pair<std::uint32_t, Rational>> entries;
  if (k + 1 >= breaks.size()) return entries;
  // Standardised exactly, then rounded once: cells at the same place relative to the mean get
  // bit-identical doubles, so their rows stay equal and merge in the quotient.
  auto standardised = [&](const Rational& t) { return to_double((t - mean) / deviation); };
  double below = standardised(breaks[k]);
  Rational total = 0;
  for (; k + 1 < breaks.size() && breaks[k] < high; ++k) {
    const double above = standardised(breaks[k + 1]);
    Rational p = quantized(standard_probability(below, above));
    below = above;
    if (sgn(p) == 0) continue;
    total += p;
    entries.emplace_back(static_cast<std::uint32_t>(k), std::move(p));
  }
  if (total > 1) remove_excess(entries, total - 1);
  return entries;
}

Rational gaussian_row_tolerance(std::size_t intervals) {
  // One entry: two tails, the subtraction's rounding (2^-52 at most) and half a quantum.
  const Rational entry =
      2 * tail_error() + 1 / power_of_two(52) + 1 / power_of_two(kQuantumBits + 1);
  // The entries' errors, at most doubled by remove_excess, bound the distance on the domain's
  // intervals; the rest of the mass moves by minus their sum, which the total-variation halving
  // absorbs; the truncated tails add their mass once.
  return 2 * Rational(static_cast<long>(intervals)) * entry + truncated_mass();
}

}  // namespace oasis::geom
