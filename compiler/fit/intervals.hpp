#pragma once
// Confidence intervals shared by the fits: the Wilson score interval of a binomial
// proportion, the observed Fisher information of a log-likelihood (a central-difference
// Hessian, inverted with Eigen) and the profile-likelihood interval of one parameter.
// All intervals are two-sided 95%.

#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

namespace oasis::fit {

// The 97.5% quantile of the standard normal (two-sided 95%).
inline constexpr double kZ95 = 1.959963984540054;
// Half the 95% quantile of chi-squared with one degree of freedom (3.841458820694124 / 2):
// the drop of the log-likelihood that bounds a profile-likelihood interval.
inline constexpr double kHalfChi2One95 = 1.920729410347062;

struct Interval {
  double low = 0.0;
  double high = 0.0;
};

// Wilson score interval for `successes` out of `trials` (> 0): never outside [0, 1], sensible
// at 0 and at `trials` successes, where the Wald interval collapses to a point.
Interval wilson_interval(double successes, double trials);

// Hessian of `f` at `x` by central differences with steps h_k = step * max(1, |x_k|), from
// the function alone (4 evaluations per off-diagonal pair, 2 per diagonal entry, plus one).
std::vector<double> numeric_hessian(const std::function<double(const std::vector<double>&)>& f,
                                    const std::vector<double>& x, double step = 1e-4);

// Hessian from an analytic gradient by central differences of the gradient, symmetrised.
std::vector<double> gradient_hessian(
    const std::function<void(const std::vector<double>&, std::vector<double>&)>& gradient,
    const std::vector<double>& x, double step = 1e-5);

// The covariance of the MLE: the inverse of the observed information `hessian` (n x n,
// row-major, the Hessian of the *negative* log-likelihood). nullopt when it is not
// positive definite (the estimate is on a boundary or the parameters are not identifiable).
std::optional<std::vector<double>> covariance_from_information(const std::vector<double>& hessian,
                                                               std::size_t n);

// The profile-likelihood 95% interval of a scalar parameter on [low, high]: the values whose
// log-likelihood is within kHalfChi2One95 of the maximum `best_value` at `best`, found by
// bisection on each side. A side whose bound is inside the set gives that bound.
// `log_likelihood` may return -infinity.
Interval profile_interval(const std::function<double(double)>& log_likelihood, double best,
                          double best_value, double low, double high);

}  // namespace oasis::fit
