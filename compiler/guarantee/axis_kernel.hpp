#pragma once
// One axis of an interval MDP row (docs/guarantees.md, "Interval rows"): where the successor's
// coordinate lands among the axis's intervals when the mean of that coordinate is known only
// to lie in [mean_low, mean_high] (an enclosure of f_i over a cell).
//
// For every interval k of the axis, P_k(m) = P(m + w ∈ [t_k, t_{k+1}]) is unimodal in the mean
// m (it rises, then falls), for a Gaussian w, a uniform w, and a point mass alike. So over the
// enclosure its minimum is at an end and its maximum at the mode clamped into the enclosure:
// the row's bounds are exact up to the evaluation of the distribution function, which is
// rounded outward by a stated slack.

#include <cstdint>
#include <vector>

#include "model/model_ir.hpp"

namespace oasis::guarantee {

// The disturbance of one axis, in doubles: Gaussian(mean, deviation), uniform on
// [mean + low, mean + high] (mean 0), or none.
struct AxisNoise {
  enum class Kind { None, Uniform, Gaussian } kind = Kind::None;
  double mean = 0;
  double deviation = 0;  // Gaussian
  double low = 0;        // uniform
  double high = 0;       // uniform
};

// Converts the spec's disturbance; the exact rationals are rounded to the nearest double (an
// error of one part in 2^53, far inside the slack of kProbabilitySlack).
AxisNoise axis_noise(const model::DisturbanceModel& disturbance);

// The interval probabilities of one axis for one (cell, action): `first` is the first interval
// index with an entry and lower[k], upper[k] bound the probability of interval first + k.
// `outside_*` bound the probability of leaving the axis's range (below or above), and
// `truncated` bounds the mass of the intervals without an entry (Gaussian tails; lower bound 0).
// Invariants: 0 <= lower <= upper <= 1 entrywise, sum of lowers <= 1 <= sum of uppers +
// truncated (with the outside terms).
struct AxisRow {
  std::uint32_t first = 0;
  std::vector<double> lower;
  std::vector<double> upper;
  double outside_lower = 0;
  double outside_upper = 0;
  double truncated = 0;
};

// Absolute slack added outward to every probability (lower bounds down, upper bounds up): it
// covers erfc's error (glibc: a few ulps, under 1e-15 absolutely), the rounding of the
// standardised arguments, and the subtractions. docs/guarantees.md states the argument.
inline constexpr double kProbabilitySlack = 1e-13;

// A Gaussian row covers the intervals within this many deviations of the enclosure; the mass
// beyond, P(|Z| >= 7.2) < 6.2e-13, is `truncated`.
inline constexpr double kTruncationDeviations = 7.2;
inline constexpr double kTruncatedMass = 6.3e-13;

// `breaks` are the axis's breakpoints t_0 < ... < t_n (the grid's intervals are
// [t_k, t_{k+1}), the last one closed).
AxisRow axis_row(const AxisNoise& noise, double mean_low, double mean_high,
                 const std::vector<double>& breaks);

}  // namespace oasis::guarantee
