#include "fit/switching_fit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <nlopt.hpp>

namespace oasis::fit {
namespace {

constexpr double kLogitBound = 30.0;
constexpr double kFloor = -1e300;  // what NLopt sees instead of -infinity

// Counts evaluations, reports progress and remembers the best point seen.
class Objective {
 public:
  Objective(const FilterModel& model, const std::vector<LoggedRun>& runs,
            const SwitchingFitOptions& options)
      : model_(model), runs_(runs), options_(options) {}

  double matrix(const std::vector<double>& switching) {
    const double value = log_likelihood(model_, switching, runs_);
    ++evaluations_;
    if (options_.progress) options_.progress(evaluations_, value);
    return value;
  }

  double symmetric(double p_stay) {
    return matrix(symmetric_switching(model_.num_contexts, std::clamp(p_stay, 0.0, 1.0)));
  }

  std::size_t evaluations() const { return evaluations_; }
  std::uint32_t n() const { return model_.num_contexts; }

 private:
  const FilterModel& model_;
  const std::vector<LoggedRun>& runs_;
  const SwitchingFitOptions& options_;
  std::size_t evaluations_ = 0;
};

// Row-stochastic matrix from logits: row i has theta_ii = 0 and the N - 1 others in order.
std::vector<double> softmax_matrix(std::uint32_t n, const std::vector<double>& theta) {
  std::vector<double> matrix(static_cast<std::size_t>(n) * n);
  for (std::uint32_t i = 0; i < n; ++i) {
    std::vector<double> logits(n, 0.0);
    std::size_t k = static_cast<std::size_t>(i) * (n - 1);
    for (std::uint32_t j = 0; j < n; ++j)
      if (j != i) logits[j] = theta[k++];
    const double top = *std::max_element(logits.begin(), logits.end());
    double sum = 0.0;
    for (double& l : logits)
      sum += (l = std::exp(l - top));
    for (std::uint32_t j = 0; j < n; ++j)
      matrix[static_cast<std::size_t>(i) * n + j] = logits[j] / sum;
  }
  return matrix;
}

struct Maximum {
  std::vector<double> x;
  double value = -std::numeric_limits<double>::infinity();
};

// Maximises `f` with NLopt `algorithm` in [low, high] from `start`; the best point seen wins
// even when NLopt stops on a round-off or evaluation limit.
Maximum maximise(nlopt::algorithm algorithm,
                 const std::function<double(const std::vector<double>&)>& f,
                 std::vector<double> start, const std::vector<double>& low,
                 const std::vector<double>& high, double initial_step) {
  Maximum best{start, f(start)};
  struct Data {
    const std::function<double(const std::vector<double>&)>* f;
    Maximum* best;
  } data{&f, &best};
  nlopt::opt opt(algorithm, static_cast<unsigned>(start.size()));
  opt.set_lower_bounds(low);
  opt.set_upper_bounds(high);
  opt.set_initial_step(initial_step);
  opt.set_xtol_abs(1e-7);
  opt.set_ftol_abs(1e-9);
  opt.set_maxeval(2000);
  opt.set_max_objective(
      [](const std::vector<double>& x, std::vector<double>&, void* raw) {
        auto* d = static_cast<Data*>(raw);
        const double value = (*d->f)(x);
        if (value > d->best->value) *d->best = {x, value};
        return std::isfinite(value) ? value : kFloor;
      },
      &data);
  double found = 0.0;
  try {
    opt.optimize(start, found);
  } catch (const nlopt::roundoff_limited&) {
    // the best point seen is kept
  } catch (const std::runtime_error&) {
    // NLopt's generic failure: the best point seen is still a valid estimate
  }
  return best;
}

void fit_symmetric(Objective& objective, SwitchingFit& fit) {
  // A grid brackets the maximum (the likelihood may be flat or -infinity near the bounds).
  constexpr int kGrid = 40;
  int best_k = 0;
  double best_value = -std::numeric_limits<double>::infinity();
  for (int k = 0; k <= kGrid; ++k) {
    const double value = objective.symmetric(static_cast<double>(k) / kGrid);
    if (value > best_value) {
      best_value = value;
      best_k = k;
    }
  }
  const double low = std::max(0, best_k - 1) / static_cast<double>(kGrid);
  const double high = std::min(kGrid, best_k + 1) / static_cast<double>(kGrid);
  const auto f = [&](const std::vector<double>& x) { return objective.symmetric(x[0]); };
  const Maximum best = maximise(nlopt::LN_COBYLA, f, {static_cast<double>(best_k) / kGrid}, {low},
                                {high}, (high - low) / 4.0);
  fit.p_stay = best.x[0];
  fit.log_likelihood = best.value;
  fit.matrix = symmetric_switching(objective.n(), fit.p_stay);
  fit.p_stay_interval = profile_interval([&](double p) { return objective.symmetric(p); },
                                         fit.p_stay, fit.log_likelihood, 0.0, 1.0);
  // Observed information, when the estimate is inside (0, 1) far enough for the stencil.
  const double h = 1e-4;
  if (fit.p_stay > 2 * h && fit.p_stay < 1.0 - 2 * h) {
    const auto minus_l = [&](const std::vector<double>& x) { return -objective.symmetric(x[0]); };
    const std::vector<double> hessian = numeric_hessian(minus_l, {fit.p_stay}, h);
    if (hessian[0] > 0.0 && std::isfinite(hessian[0]))
      fit.p_stay_error = 1.0 / std::sqrt(hessian[0]);
  }
  fit.optimiser = "41-point grid, then NLopt LN_COBYLA";
}

void fit_full(Objective& objective, SwitchingFit& fit) {
  const std::uint32_t n = objective.n();
  const std::size_t dims = static_cast<std::size_t>(n) * (n - 1);
  // Start from the symmetric estimate (p_stay clipped away from 0 and 1).
  const double p = std::clamp(fit.p_stay, 1e-3, 1.0 - 1e-3);
  std::vector<double> start(dims, std::log((1.0 - p) / static_cast<double>(n - 1) / p));
  const auto f = [&](const std::vector<double>& theta) {
    return objective.matrix(softmax_matrix(n, theta));
  };
  const Maximum best = maximise(nlopt::LN_BOBYQA, f, start, std::vector<double>(dims, -kLogitBound),
                                std::vector<double>(dims, kLogitBound), 0.5);
  fit.matrix = softmax_matrix(n, best.x);
  fit.log_likelihood = best.value;
  fit.optimiser = "41-point grid and NLopt LN_COBYLA (symmetric start), then NLopt LN_BOBYQA";

  // Observed information over the logits that are not on their bounds.
  std::vector<std::size_t> free;
  std::vector<bool> row_on_bound(n, false);
  for (std::size_t k = 0; k < dims; ++k) {
    if (std::fabs(best.x[k]) < kLogitBound - 1.0) {
      free.push_back(k);
    } else {
      row_on_bound[k / (n - 1)] = true;
    }
  }
  fit.entry_intervals.assign(static_cast<std::size_t>(n) * n, std::nullopt);
  if (free.empty()) return;
  const auto minus_l = [&](const std::vector<double>& sub) {
    std::vector<double> theta = best.x;
    for (std::size_t k = 0; k < free.size(); ++k)
      theta[free[k]] = sub[k];
    return -f(theta);
  };
  std::vector<double> sub;
  for (std::size_t k : free)
    sub.push_back(best.x[k]);
  const std::optional<std::vector<double>> covariance =
      covariance_from_information(numeric_hessian(minus_l, sub, 1e-4), free.size());
  if (!covariance) return;
  // Delta method per row: p_ij = softmax_j(theta_i), d p_ij / d theta_ik = p_ij (d_jk - p_ik).
  std::vector<std::size_t> position(dims, free.size());  // index into `free`, or none
  for (std::size_t k = 0; k < free.size(); ++k)
    position[free[k]] = k;
  for (std::uint32_t i = 0; i < n; ++i) {
    if (row_on_bound[i]) continue;
    const double* row = fit.matrix.data() + static_cast<std::size_t>(i) * n;
    std::vector<std::uint32_t> columns;  // the column of each logit of row i
    for (std::uint32_t j = 0; j < n; ++j)
      if (j != i) columns.push_back(j);
    for (std::uint32_t j = 0; j < n; ++j) {
      double variance = 0.0;
      for (std::size_t a = 0; a < columns.size(); ++a) {
        const double ga = row[j] * ((j == columns[a] ? 1.0 : 0.0) - row[columns[a]]);
        const std::size_t pa = position[static_cast<std::size_t>(i) * (n - 1) + a];
        for (std::size_t b = 0; b < columns.size(); ++b) {
          const double gb = row[j] * ((j == columns[b] ? 1.0 : 0.0) - row[columns[b]]);
          const std::size_t pb = position[static_cast<std::size_t>(i) * (n - 1) + b];
          variance += ga * gb * (*covariance)[pa * free.size() + pb];
        }
      }
      const double half = kZ95 * std::sqrt(std::max(0.0, variance));
      fit.entry_intervals[static_cast<std::size_t>(i) * n + j] =
          Interval{std::max(0.0, row[j] - half), std::min(1.0, row[j] + half)};
    }
  }
}

}  // namespace

std::optional<SwitchingFit> fit_switching(const FilterModel& model,
                                          const std::vector<LoggedRun>& runs,
                                          const SwitchingFitOptions& options, std::string& error) {
  if (model.num_contexts < 2) {
    error = "the spec has one context: there is no switching model to fit";
    return std::nullopt;
  }
  SwitchingFit fit;
  fit.full = options.full;
  fit.num_contexts = model.num_contexts;
  for (const LoggedRun& run : runs) {
    if (run.steps.empty()) continue;
    ++fit.runs;
    fit.steps += run.steps.size();
  }
  if (fit.steps == 0) {
    error = "the logs have no steps";
    return std::nullopt;
  }
  Objective objective(model, runs, options);
  fit_symmetric(objective, fit);
  if (!std::isfinite(fit.log_likelihood)) {
    error = model.detection_epsilon > 0.0
                ? "no switching model gives the logs a positive likelihood"
                : "no switching model explains every logged reward (log-likelihood -inf): the "
                  "logs are noisy or do not come from this spec; give a detection epsilon > 0";
    return std::nullopt;
  }
  if (options.full) fit_full(objective, fit);
  fit.evaluations = objective.evaluations();
  return fit;
}

}  // namespace oasis::fit
