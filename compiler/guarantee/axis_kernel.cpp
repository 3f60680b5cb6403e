#include "guarantee/axis_kernel.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace oasis::guarantee {
namespace {

double lower_bound(double p) {
  return std::clamp(p - kProbabilitySlack, 0.0, 1.0);
}
double upper_bound(double p) {
  return std::clamp(p + kProbabilitySlack, 0.0, 1.0);
}

// P(Z <= z) and P(Z > z), each taken from erfc on the side where it is at most 1/2, so that a
// small probability keeps its digits.
double normal_cdf(double z) {
  return 0.5 * std::erfc(-z / std::numbers::sqrt2);
}
double normal_tail(double z) {
  return 0.5 * std::erfc(z / std::numbers::sqrt2);
}

// P(a <= Z <= b) for a <= b, as a difference of the two tails on the same side of 0.
double normal_mass(double a, double b) {
  if (a >= 0) return std::max(0.0, normal_tail(a) - normal_tail(b));
  if (b <= 0) return std::max(0.0, normal_cdf(b) - normal_cdf(a));
  return std::max(0.0, 1.0 - normal_cdf(a) - normal_tail(b));
}

// The probability that the successor coordinate m + w lands in [low, high].
double mass_in(const AxisNoise& noise, double m, double low, double high) {
  switch (noise.kind) {
    case AxisNoise::Kind::Gaussian:
      return normal_mass((low - m - noise.mean) / noise.deviation,
                         (high - m - noise.mean) / noise.deviation);
    case AxisNoise::Kind::Uniform: {
      const double from = std::max(low, m + noise.low);
      const double to = std::min(high, m + noise.high);
      return std::max(0.0, to - from) / (noise.high - noise.low);
    }
    case AxisNoise::Kind::None:
      return m >= low && m <= high ? 1.0 : 0.0;
  }
  return 0;
}

// The mean at which mass_in(., low, high) is largest.
double mode_of(const AxisNoise& noise, double low, double high) {
  const double centre = 0.5 * (low + high);
  if (noise.kind == AxisNoise::Kind::Uniform) return centre - 0.5 * (noise.low + noise.high);
  return centre - noise.mean;
}

// The successor's coordinate lies in [reach_low, reach_high] up to the truncated tails.
void successor_reach(const AxisNoise& noise, double mean_low, double mean_high, double& reach_low,
                     double& reach_high) {
  switch (noise.kind) {
    case AxisNoise::Kind::Gaussian:
      reach_low = mean_low + noise.mean - kTruncationDeviations * noise.deviation;
      reach_high = mean_high + noise.mean + kTruncationDeviations * noise.deviation;
      return;
    case AxisNoise::Kind::Uniform:
      reach_low = mean_low + noise.low;
      reach_high = mean_high + noise.high;
      return;
    case AxisNoise::Kind::None:
      reach_low = mean_low;
      reach_high = mean_high;
      return;
  }
}

// Point masses are decided exactly, with the grid's boundary rule: [t_k, t_{k+1}) except the
// last interval, which is closed. The bounds are 0 or 1.
AxisRow point_row(double mean_low, double mean_high, const std::vector<double>& breaks) {
  AxisRow row;
  const std::size_t n = breaks.size() - 1;
  const bool below = mean_low < breaks.front();
  const bool above = mean_high > breaks.back();
  const bool all_below = mean_high < breaks.front();
  const bool all_above = mean_low > breaks.back();
  row.outside_upper = below || above ? 1 : 0;
  row.outside_lower = all_below || all_above ? 1 : 0;
  if (all_below || all_above) return row;
  // The intervals that hold some point of [mean_low, mean_high] within the range.
  auto interval_of = [&](double x) {
    auto it = std::upper_bound(breaks.begin(), breaks.end(), x);
    const auto k = static_cast<std::size_t>(it - breaks.begin());
    return std::min(k == 0 ? 0 : k - 1, n - 1);
  };
  const std::size_t first = interval_of(std::max(mean_low, breaks.front()));
  const std::size_t last = interval_of(std::min(mean_high, breaks.back()));
  row.first = static_cast<std::uint32_t>(first);
  const bool certain = first == last && !below && !above;
  for (std::size_t k = first; k <= last; ++k) {
    row.lower.push_back(certain ? 1 : 0);
    row.upper.push_back(1);
  }
  return row;
}

}  // namespace

AxisNoise axis_noise(const model::DisturbanceModel& disturbance) {
  AxisNoise noise;
  switch (disturbance.kind) {
    case model::DisturbanceModel::Kind::None:
      break;
    case model::DisturbanceModel::Kind::Bounded:
      noise.kind = AxisNoise::Kind::Uniform;
      noise.low = to_double(disturbance.first);
      noise.high = to_double(disturbance.second);
      // A zero-width interval is a point: no disturbance, shifted.
      if (noise.low == noise.high) noise.kind = AxisNoise::Kind::None;
      break;
    case model::DisturbanceModel::Kind::Gaussian:
      noise.kind = AxisNoise::Kind::Gaussian;
      noise.mean = to_double(disturbance.first);
      noise.deviation = to_double(disturbance.second);
      break;
  }
  return noise;
}

AxisRow axis_row(const AxisNoise& noise, double mean_low, double mean_high,
                 const std::vector<double>& breaks) {
  if (noise.kind == AxisNoise::Kind::None) {
    // A disturbance of zero width shifts the mean: fold its offset in.
    return point_row(mean_low + noise.low, mean_high + noise.low, breaks);
  }
  AxisRow row;
  const std::size_t n = breaks.size() - 1;
  double reach_low = 0;
  double reach_high = 0;
  successor_reach(noise, mean_low, mean_high, reach_low, reach_high);
  // Entries for the intervals that meet [reach_low, reach_high].
  auto first_it = std::upper_bound(breaks.begin(), breaks.end(), reach_low);
  std::size_t first =
      first_it == breaks.begin() ? 0 : static_cast<std::size_t>(first_it - breaks.begin()) - 1;
  auto last_it = std::lower_bound(breaks.begin(), breaks.end(), reach_high);
  std::size_t end = std::min(n, static_cast<std::size_t>(last_it - breaks.begin()));
  first = std::min(first, n);
  row.first = static_cast<std::uint32_t>(first);
  for (std::size_t k = first; k < end; ++k) {
    const double low = breaks[k];
    const double high = breaks[k + 1];
    const double at_low = mass_in(noise, mean_low, low, high);
    const double at_high = mass_in(noise, mean_high, low, high);
    const double peak =
        mass_in(noise, std::clamp(mode_of(noise, low, high), mean_low, mean_high), low, high);
    row.lower.push_back(lower_bound(std::min(at_low, at_high)));
    row.upper.push_back(upper_bound(std::max({at_low, at_high, peak})));
  }
  // Leaving the range: below is largest at the lowest mean, above at the highest.
  const double inf = std::numeric_limits<double>::infinity();
  const double below_max = mass_in(noise, mean_low, -inf, breaks.front());
  const double below_min = mass_in(noise, mean_high, -inf, breaks.front());
  const double above_max = mass_in(noise, mean_high, breaks.back(), inf);
  const double above_min = mass_in(noise, mean_low, breaks.back(), inf);
  row.outside_lower = lower_bound(below_min + above_min);
  row.outside_upper = upper_bound(below_max + above_max);
  const bool cut_below = first > 0 && noise.kind == AxisNoise::Kind::Gaussian;
  const bool cut_above = end < n && noise.kind == AxisNoise::Kind::Gaussian;
  if (cut_below || cut_above) row.truncated = kTruncatedMass + kProbabilitySlack;
  return row;
}

}  // namespace oasis::guarantee
