#include "fit/intervals.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

namespace oasis::fit {

Interval wilson_interval(double successes, double trials) {
  const double z2 = kZ95 * kZ95;
  const double p = successes / trials;
  const double denominator = 1.0 + z2 / trials;
  const double centre = (p + z2 / (2.0 * trials)) / denominator;
  const double half =
      kZ95 / denominator * std::sqrt(p * (1.0 - p) / trials + z2 / (4.0 * trials * trials));
  return {std::max(0.0, centre - half), std::min(1.0, centre + half)};
}

std::vector<double> numeric_hessian(const std::function<double(const std::vector<double>&)>& f,
                                    const std::vector<double>& x, double step) {
  const std::size_t n = x.size();
  std::vector<double> h(n);
  for (std::size_t k = 0; k < n; ++k)
    h[k] = step * std::max(1.0, std::fabs(x[k]));
  std::vector<double> hessian(n * n, 0.0);
  const double f0 = f(x);
  std::vector<double> y = x;
  for (std::size_t i = 0; i < n; ++i) {
    y[i] = x[i] + h[i];
    const double plus = f(y);
    y[i] = x[i] - h[i];
    const double minus = f(y);
    y[i] = x[i];
    hessian[i * n + i] = (plus - 2.0 * f0 + minus) / (h[i] * h[i]);
    for (std::size_t j = 0; j < i; ++j) {
      double sum = 0.0;
      for (const auto& [si, sj] : {std::pair{1.0, 1.0}, {1.0, -1.0}, {-1.0, 1.0}, {-1.0, -1.0}}) {
        y[i] = x[i] + si * h[i];
        y[j] = x[j] + sj * h[j];
        sum += si * sj * f(y);
      }
      y[i] = x[i];
      y[j] = x[j];
      hessian[i * n + j] = hessian[j * n + i] = sum / (4.0 * h[i] * h[j]);
    }
  }
  return hessian;
}

std::vector<double> gradient_hessian(
    const std::function<void(const std::vector<double>&, std::vector<double>&)>& gradient,
    const std::vector<double>& x, double step) {
  const std::size_t n = x.size();
  std::vector<double> hessian(n * n, 0.0);
  std::vector<double> y = x;
  std::vector<double> plus(n), minus(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double h = step * std::max(1.0, std::fabs(x[k]));
    y[k] = x[k] + h;
    gradient(y, plus);
    y[k] = x[k] - h;
    gradient(y, minus);
    y[k] = x[k];
    for (std::size_t j = 0; j < n; ++j)
      hessian[j * n + k] = (plus[j] - minus[j]) / (2.0 * h);
  }
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < i; ++j)
      hessian[i * n + j] = hessian[j * n + i] = 0.5 * (hessian[i * n + j] + hessian[j * n + i]);
  return hessian;
}

std::optional<std::vector<double>> covariance_from_information(const std::vector<double>& hessian,
                                                               std::size_t n) {
  Eigen::MatrixXd information(n, n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j)
      information(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = hessian[i * n + j];
  if (!information.allFinite()) return std::nullopt;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(information);
  if (eigen.info() != Eigen::Success) return std::nullopt;
  const Eigen::VectorXd values = eigen.eigenvalues();
  const double largest = values.cwiseAbs().maxCoeff();
  if (!(values.minCoeff() > 1e-12 * largest)) return std::nullopt;
  const Eigen::MatrixXd covariance =
      eigen.eigenvectors() * values.cwiseInverse().asDiagonal() * eigen.eigenvectors().transpose();
  std::vector<double> out(n * n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j)
      out[i * n + j] = covariance(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
  return out;
}

Interval profile_interval(const std::function<double(double)>& log_likelihood, double best,
                          double best_value, double low, double high) {
  const double floor = best_value - kHalfChi2One95;
  const auto inside = [&](double x) {
    const double value = log_likelihood(x);
    return std::isfinite(value) && value >= floor;
  };
  // Bisection between a point inside (the estimate) and one outside.
  const auto bound = [&](double outer) {
    if (inside(outer)) return outer;
    double in = best, out = outer;
    for (int iteration = 0; iteration < 60 && std::fabs(out - in) > 1e-9; ++iteration) {
      const double middle = 0.5 * (in + out);
      (inside(middle) ? in : out) = middle;
    }
    return 0.5 * (in + out);
  };
  return {bound(low), bound(high)};
}

}  // namespace oasis::fit
