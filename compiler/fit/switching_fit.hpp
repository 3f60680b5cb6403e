#pragma once
// Maximum-likelihood fit of the switching model p(phi_t | phi_{t-1}) from logged runs: the
// maximiser of the forward algorithm's marginal likelihood (fit/forward_algorithm.hpp),
// found with NLopt.
//
// Symmetric model (`switching stay p;`): one parameter p_stay in [0, 1]. A grid of 41 values
// brackets the maximum, then NLopt's derivative-free, bounded LN_COBYLA refines it within
// the bracket (LN_BOBYQA, used for the full model, needs two or more variables).
// 95% interval: profile likelihood (the p_stay whose log-likelihood is within
// chi2_1(0.95) / 2 = 1.92 of the maximum), which stays inside [0, 1] and is honest near the
// bounds; the standard error from the observed information is printed beside it.
// Full model (`switching { ... }`): row i is a softmax of logits theta_ij (theta_ii = 0),
// N (N - 1) parameters in [-30, 30], maximised with LN_BOBYQA from the symmetric estimate.
// 95% intervals per entry: Wald intervals from the observed information in the logits (a
// central-difference Hessian inverted with Eigen) carried to the probabilities by the delta
// method and clipped to [0, 1]; none for an entry whose logits sit on their bound (an entry
// estimated as 0 or 1).

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "fit/forward_algorithm.hpp"
#include "fit/intervals.hpp"

namespace oasis::fit {

struct SwitchingFitOptions {
  bool full = false;
  // Called after every likelihood evaluation with its number and value (progress).
  std::function<void(std::size_t evaluation, double log_likelihood)> progress;
};

struct SwitchingFit {
  bool full = false;
  std::uint32_t num_contexts = 0;
  // Symmetric model.
  double p_stay = 0.0;
  Interval p_stay_interval;            // profile likelihood, 95%
  std::optional<double> p_stay_error;  // standard error (observed information)
  // Both models: the fitted matrix, row-major; full model: an interval per entry.
  std::vector<double> matrix;
  std::vector<std::optional<Interval>> entry_intervals;  // full model only
  double log_likelihood = 0.0;
  std::size_t evaluations = 0;
  std::size_t runs = 0;
  std::size_t steps = 0;
  std::string optimiser;  // the NLopt algorithm(s) used
};

// nullopt with `error` when there is nothing to fit (fewer than two contexts, no steps) or
// when no switching model explains the runs (log-likelihood -infinity everywhere: raise the
// detection epsilon).
std::optional<SwitchingFit> fit_switching(const FilterModel& model,
                                          const std::vector<LoggedRun>& runs,
                                          const SwitchingFitOptions& options, std::string& error);

}  // namespace oasis::fit
