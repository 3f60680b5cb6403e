#pragma once
// Maximum-likelihood fit of distance-dependent depth noise, the measurement of the paper's
// appendix (Fig. "Depth measurements ... the sensor noise (standard deviation) increases with
// distance"), from calibration pairs (true distance d, measured distance m):
//
//   m = d + bias(d) + sigma(d) * e,   e ~ Normal(0, 1) independent,
//   sigma(d) = a + b d + c d^2        (degree 2; degree 1 drops c, degree 0 keeps a),
//   bias(d)  = 0 | b0 | b0 + b1 d     (none | constant, the default | linear).
//
// Why a bias: a depth camera's mean error is rarely zero (a mounting offset, a scale error
// growing with distance); fitting sigma with the bias forced to 0 would fold the offset into
// sigma and overstate the noise. The observation model of the spec has no bias term: the fit
// reports it so that perception can subtract it.
//
// The negative log-likelihood sum_k [log sigma(d_k) + (r_k - bias(d_k))^2 / (2 sigma(d_k)^2)]
// (r = m - d) is minimised with NLopt's LD_SLSQP (analytic gradient) subject to
// sigma(d) >= a small floor at 33 points spanning the data's range and at every distinct
// calibration distance (up to 200), linear constraints in (a, b, c); LN_COBYLA is the
// fallback if SLSQP fails. Parameters are scaled (d by its maximum, r by its standard
// deviation) so that the optimiser sees numbers near 1. 95% intervals: Wald, from the
// observed information (the Hessian of the negative log-likelihood by central differences of
// the analytic gradient, inverted with Eigen); sigma(d) at a distance by the delta method.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "fit/csv_table.hpp"
#include "fit/intervals.hpp"

namespace oasis::fit {

struct DepthPair {
  double true_distance = 0.0;
  double measured = 0.0;
};

// Appends the pairs of `table` (columns true_m, measured_m; others ignored). false after
// reporting errors (missing columns, bad or negative numbers).
bool read_calibration(const CsvTable& table, std::vector<DepthPair>& pairs,
                      DiagnosticEngine& diagnostics);

enum class DepthBias : std::uint32_t { kNone, kConstant, kLinear };

struct DepthNoiseOptions {
  std::uint32_t degree = 2;  // of sigma(d), 0..2
  DepthBias bias = DepthBias::kConstant;
};

struct DepthNoiseFit {
  std::vector<double> bias;   // b0[, b1]; empty for DepthBias::kNone
  std::vector<double> sigma;  // a[, b[, c]]
  // Over the parameters [bias..., sigma...]; empty when the observed information is not
  // positive definite (then `intervals` is empty too).
  std::vector<double> covariance;
  std::vector<Interval> intervals;  // Wald 95% per parameter
  double log_likelihood = 0.0;      // including the constant -n/2 log(2 pi)
  std::size_t pairs = 0;
  std::size_t distinct_distances = 0;
  double range_low = 0.0;
  double range_high = 0.0;
  bool floor_active = false;  // sigma(d) reaches the positivity floor somewhere on the range
  std::string optimiser;
  std::size_t evaluations = 0;

  [[nodiscard]] double sigma_at(double d) const;
  [[nodiscard]] double bias_at(double d) const;
  // Delta method on the covariance; nullopt without one.
  [[nodiscard]] std::optional<Interval> sigma_interval(double d) const;
};

// nullopt with `error` when the data cannot identify the model (too few pairs or distinct
// distances, no spread in the measurements) or no optimiser converged.
std::optional<DepthNoiseFit> fit_depth_noise(const std::vector<DepthPair>& pairs,
                                             const DepthNoiseOptions& options, std::string& error);

}  // namespace oasis::fit
