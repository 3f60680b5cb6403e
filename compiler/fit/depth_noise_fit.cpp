#include "fit/depth_noise_fit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <set>

#include <Eigen/Dense>
#include <nlopt.hpp>

namespace oasis::fit {
namespace {

constexpr double kSigmaFloor = 1e-6;  // in units of the residuals' standard deviation
constexpr std::size_t kMaxConstrainedDistances = 200;

// c[0] + c[1] u + ... + c[terms-1] u^(terms-1).
double poly(const double* c, std::size_t terms, double u) {
  double value = 0.0, power = 1.0;
  for (std::size_t k = 0; k < terms; ++k, power *= u)
    value += c[k] * power;
  return value;
}

// The problem in scaled units: u = d / D, e = (m - d) / R.
class ScaledProblem {
 public:
  ScaledProblem(std::vector<double> u, std::vector<double> e, std::size_t bias_terms,
                std::size_t sigma_terms)
      : u_(std::move(u)), e_(std::move(e)), nb_(bias_terms), ns_(sigma_terms) {}

  std::size_t dimension() const { return nb_ + ns_; }
  std::size_t bias_terms() const { return nb_; }
  std::size_t sigma_terms() const { return ns_; }

  // Negative log-likelihood without the constants; fills `gradient` when non-empty.
  double value(const std::vector<double>& x, std::vector<double>& gradient) const {
    if (!gradient.empty()) std::fill(gradient.begin(), gradient.end(), 0.0);
    double sum = 0.0;
    for (std::size_t k = 0; k < u_.size(); ++k) {
      const double mu = poly(x.data(), nb_, u_[k]);
      const double sigma = poly(x.data() + nb_, ns_, u_[k]);
      if (!(sigma > 0.0)) return std::numeric_limits<double>::max();
      const double z = e_[k] - mu;
      sum += std::log(sigma) + z * z / (2.0 * sigma * sigma);
      if (gradient.empty()) continue;
      const double d_mu = -z / (sigma * sigma);
      const double d_sigma = 1.0 / sigma - z * z / (sigma * sigma * sigma);
      double power = 1.0;
      for (std::size_t j = 0; j < std::max(nb_, ns_); ++j, power *= u_[k]) {
        if (j < nb_) gradient[j] += d_mu * power;
        if (j < ns_) gradient[nb_ + j] += d_sigma * power;
      }
    }
    return sum;
  }

 private:
  std::vector<double> u_, e_;
  std::size_t nb_, ns_;
};

// Least squares fit of y on the powers 0..terms-1 of u.
std::vector<double> least_squares(const std::vector<double>& u, const std::vector<double>& y,
                                  std::size_t terms) {
  Eigen::MatrixXd a(static_cast<Eigen::Index>(u.size()), static_cast<Eigen::Index>(terms));
  Eigen::VectorXd b(static_cast<Eigen::Index>(u.size()));
  for (std::size_t k = 0; k < u.size(); ++k) {
    double power = 1.0;
    for (std::size_t j = 0; j < terms; ++j, power *= u[k])
      a(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(j)) = power;
    b(static_cast<Eigen::Index>(k)) = y[k];
  }
  const Eigen::VectorXd solution = a.colPivHouseholderQr().solve(b);
  return {solution.data(), solution.data() + solution.size()};
}

struct ConstraintData {
  double u;
  std::size_t offset;  // index of a
  std::size_t terms;
};

double floor_constraint(unsigned n, const double* x, double* grad, void* raw) {
  const auto* c = static_cast<const ConstraintData*>(raw);
  if (grad != nullptr) {
    std::fill(grad, grad + n, 0.0);
    double power = 1.0;
    for (std::size_t j = 0; j < c->terms; ++j, power *= c->u)
      grad[c->offset + j] = -power;
  }
  return kSigmaFloor - poly(x + c->offset, c->terms, c->u);
}

struct Solution {
  std::vector<double> x;
  double value = std::numeric_limits<double>::infinity();
  std::size_t evaluations = 0;
};

Solution minimise(nlopt::algorithm algorithm, const ScaledProblem& problem,
                  const std::vector<double>& start, std::vector<ConstraintData>& constraints) {
  struct Data {
    const ScaledProblem* problem;
    Solution* best;
  };
  Solution best{start, std::numeric_limits<double>::infinity(), 0};
  Data data{&problem, &best};
  nlopt::opt opt(algorithm, static_cast<unsigned>(problem.dimension()));
  opt.set_min_objective(
      [](const std::vector<double>& x, std::vector<double>& grad, void* raw) {
        auto* d = static_cast<Data*>(raw);
        const double value = d->problem->value(x, grad);
        ++d->best->evaluations;
        if (value < d->best->value) {
          d->best->value = value;
          d->best->x = x;
        }
        return value;
      },
      &data);
  for (ConstraintData& c : constraints)
    opt.add_inequality_constraint(floor_constraint, &c, 1e-10);
  opt.set_xtol_rel(1e-10);
  opt.set_ftol_rel(1e-13);
  opt.set_maxeval(20000);
  if (algorithm == nlopt::LN_COBYLA) opt.set_initial_step(0.05);
  std::vector<double> x = start;
  double found = 0.0;
  try {
    opt.optimize(x, found);
  } catch (const nlopt::roundoff_limited&) {
  } catch (const std::runtime_error&) {
  } catch (const std::invalid_argument&) {
  }
  return best;
}

}  // namespace

bool read_calibration(const CsvTable& table, std::vector<DepthPair>& pairs,
                      DiagnosticEngine& diagnostics) {
  const auto true_column = table.column("true_m");
  const auto measured_column = table.column("measured_m");
  if (!true_column) return missing_column(table, "true_m", diagnostics);
  if (!measured_column) return missing_column(table, "measured_m", diagnostics);
  const std::size_t errors_before = diagnostics.error_count();
  for (const CsvRow& row : table.rows) {
    if (diagnostics.should_stop()) break;
    const CsvCell& true_cell = row.cells[*true_column];
    const auto d = parse_number(true_cell, "the true distance", diagnostics);
    const auto m = parse_number(row.cells[*measured_column], "the measured distance", diagnostics);
    if (d && *d < 0.0) {
      diagnostics.error(true_cell.where, "a distance cannot be negative");
      continue;
    }
    if (d && m) pairs.push_back({*d, *m});
  }
  return diagnostics.error_count() == errors_before;
}

double DepthNoiseFit::sigma_at(double d) const {
  return poly(sigma.data(), sigma.size(), d);
}

double DepthNoiseFit::bias_at(double d) const {
  return poly(bias.data(), bias.size(), d);
}

std::optional<Interval> DepthNoiseFit::sigma_interval(double d) const {
  if (covariance.empty()) return std::nullopt;
  const std::size_t p = bias.size() + sigma.size();
  std::vector<double> g(p, 0.0);
  double power = 1.0;
  for (std::size_t j = 0; j < sigma.size(); ++j, power *= d)
    g[bias.size() + j] = power;
  double variance = 0.0;
  for (std::size_t i = 0; i < p; ++i)
    for (std::size_t j = 0; j < p; ++j)
      variance += g[i] * g[j] * covariance[i * p + j];
  const double half = kZ95 * std::sqrt(std::max(0.0, variance));
  const double value = sigma_at(d);
  return Interval{std::max(0.0, value - half), value + half};
}

std::optional<DepthNoiseFit> fit_depth_noise(const std::vector<DepthPair>& pairs,
                                             const DepthNoiseOptions& options, std::string& error) {
  const std::size_t nb = options.bias == DepthBias::kNone       ? 0
                         : options.bias == DepthBias::kConstant ? 1
                                                                : 2;
  const std::size_t ns = options.degree + 1;
  if (options.degree > 2) {
    error = "the degree of sigma(d) must be 0, 1 or 2";
    return std::nullopt;
  }
  if (pairs.empty()) {
    error = "the calibration has no pairs";
    return std::nullopt;
  }
  std::set<double> distinct;
  double d_max = 0.0;
  for (const DepthPair& pair : pairs) {
    distinct.insert(pair.true_distance);
    d_max = std::max(d_max, pair.true_distance);
  }
  const std::size_t needed = std::max(ns, nb);
  if (distinct.size() < needed) {
    error = "sigma(d) of degree " + std::to_string(options.degree) +
            (nb == 2 ? " with a linear bias" : "") + " needs pairs at " + std::to_string(needed) +
            " or more distinct true distances, the calibration has " +
            std::to_string(distinct.size()) + " (lower --degree or --bias)";
    return std::nullopt;
  }
  if (pairs.size() < nb + ns + 1) {
    error = "too few pairs: " + std::to_string(pairs.size()) + " for " + std::to_string(nb + ns) +
            " parameters";
    return std::nullopt;
  }
  const double scale_d = d_max > 0.0 ? d_max : 1.0;
  std::vector<double> u, r;
  for (const DepthPair& pair : pairs) {
    u.push_back(pair.true_distance / scale_d);
    r.push_back(pair.measured - pair.true_distance);
  }
  // Residual scale: the spread of m - d around its least-squares bias.
  std::vector<double> spread_fit = least_squares(u, r, std::max<std::size_t>(nb, 1));
  double ss = 0.0;
  for (std::size_t k = 0; k < u.size(); ++k) {
    const double z = r[k] - poly(spread_fit.data(), spread_fit.size(), u[k]);
    ss += z * z;
  }
  const double scale_r = std::sqrt(ss / static_cast<double>(u.size()));
  if (!std::isfinite(scale_r)) {
    error = "the measurements are too far from the true distances to fit (overflow)";
    return std::nullopt;
  }
  if (!(scale_r > 0.0)) {
    error = "the measurements have no spread around the true distances: there is no noise to fit";
    return std::nullopt;
  }
  std::vector<double> e(r.size());
  for (std::size_t k = 0; k < r.size(); ++k)
    e[k] = r[k] / scale_r;

  // Start: least-squares bias, then |residual| * sqrt(pi / 2) (the mean absolute value of a
  // normal is sigma sqrt(2 / pi)) regressed on the powers of u; a constant if that is not
  // positive on the range.
  std::vector<double> start;
  std::vector<double> bias_start = nb ? least_squares(u, e, nb) : std::vector<double>{};
  start.insert(start.end(), bias_start.begin(), bias_start.end());
  std::vector<double> absolute(e.size());
  for (std::size_t k = 0; k < e.size(); ++k)
    absolute[k] =
        std::fabs(e[k] - poly(bias_start.data(), nb, u[k])) * std::sqrt(std::numbers::pi / 2.0);
  std::vector<double> sigma_start = least_squares(u, absolute, ns);
  const double u_low = *distinct.begin() / scale_d;
  const double u_high = *distinct.rbegin() / scale_d;
  std::vector<double> grid;
  for (int k = 0; k <= 32; ++k)
    grid.push_back(u_low + (u_high - u_low) * k / 32.0);
  if (distinct.size() <= kMaxConstrainedDistances)
    for (double d : distinct)
      grid.push_back(d / scale_d);
  double lowest = std::numeric_limits<double>::infinity();
  for (double g : grid)
    lowest = std::min(lowest, poly(sigma_start.data(), ns, g));
  if (!(lowest > 0.05)) {
    sigma_start.assign(ns, 0.0);
    sigma_start[0] = 1.0;
  }
  start.insert(start.end(), sigma_start.begin(), sigma_start.end());

  const ScaledProblem problem(u, e, nb, ns);
  std::vector<ConstraintData> constraints;
  for (double g : grid)
    constraints.push_back({g, nb, ns});
  DepthNoiseFit fit;
  Solution best = minimise(nlopt::LD_SLSQP, problem, start, constraints);
  fit.optimiser = "NLopt LD_SLSQP";
  fit.evaluations = best.evaluations;
  if (!std::isfinite(best.value) || best.value >= std::numeric_limits<double>::max()) {
    best = minimise(nlopt::LN_COBYLA, problem, start, constraints);
    fit.optimiser = "NLopt LN_COBYLA (LD_SLSQP failed)";
    fit.evaluations += best.evaluations;
  }
  if (!std::isfinite(best.value) || best.value >= std::numeric_limits<double>::max()) {
    error = "the optimiser found no sigma(d) > 0 that explains the pairs";
    return std::nullopt;
  }

  // Back to metres: b0, a scale by R; b1, b by R / D; c by R / D^2.
  std::vector<double> scale;
  for (std::size_t j = 0; j < nb; ++j)
    scale.push_back(scale_r / std::pow(scale_d, static_cast<double>(j)));
  for (std::size_t j = 0; j < ns; ++j)
    scale.push_back(scale_r / std::pow(scale_d, static_cast<double>(j)));
  const std::size_t p = nb + ns;
  for (std::size_t j = 0; j < p; ++j)
    (j < nb ? fit.bias : fit.sigma).push_back(best.x[j] * scale[j]);
  const double n = static_cast<double>(pairs.size());
  fit.log_likelihood =
      -(best.value + n * std::log(scale_r) + 0.5 * n * std::log(2.0 * std::numbers::pi));
  fit.pairs = pairs.size();
  fit.distinct_distances = distinct.size();
  fit.range_low = *distinct.begin();
  fit.range_high = *distinct.rbegin();
  for (double g : grid)
    if (poly(best.x.data() + nb, ns, g) < 10.0 * kSigmaFloor) fit.floor_active = true;

  const auto gradient = [&](const std::vector<double>& x, std::vector<double>& g) {
    g.assign(p, 0.0);
    problem.value(x, g);
  };
  const std::optional<std::vector<double>> covariance =
      covariance_from_information(gradient_hessian(gradient, best.x), p);
  if (covariance && !fit.floor_active) {
    fit.covariance.resize(p * p);
    for (std::size_t i = 0; i < p; ++i)
      for (std::size_t j = 0; j < p; ++j)
        fit.covariance[i * p + j] = (*covariance)[i * p + j] * scale[i] * scale[j];
    for (std::size_t j = 0; j < p; ++j) {
      const double value = j < nb ? fit.bias[j] : fit.sigma[j - nb];
      const double half = kZ95 * std::sqrt(fit.covariance[j * p + j]);
      fit.intervals.push_back({value - half, value + half});
    }
  }
  return fit;
}

}  // namespace oasis::fit
