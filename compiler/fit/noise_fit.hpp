#pragma once
// Maximum-likelihood fit of the discrete state-noise model p(observed | true) from labelled
// pairs (docs/fitting.md): a CSV with the columns true_state and observed_state (state names
// of the spec), one labelled observation per row; other columns are ignored.
//
// The likelihood is multinomial, so the MLE is in closed form, from the counts n(s, o):
//  * symmetric model (`state noise sigma;`, P(o != s) = sigma, the wrong state uniform among
//    the others): sigma = (pairs with o != s) / (all pairs). The uniform spread over wrong
//    states does not involve sigma, so this is the MLE whatever the wrong states were.
//    95% interval: Wilson score interval of that binomial proportion.
//  * confusion matrix: p(o | s) = n(s, o) / n(s); 95% interval per entry: Wilson on n(s, o)
//    out of n(s). A true state with no pairs gets the symmetric estimate's row (a warning).
//    An optional pseudo-count adds to every cell first (a posterior mean under a symmetric
//    Dirichlet prior, no longer the MLE), so that unseen confusions are not impossible.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "fit/csv_table.hpp"
#include "fit/intervals.hpp"

namespace oasis::fit {

// n(s, o), row-major [S * S], row = true state.
struct NoiseCounts {
  std::uint32_t num_states = 0;
  std::vector<std::uint64_t> counts;

  [[nodiscard]] std::uint64_t total() const;
  [[nodiscard]] std::uint64_t wrong() const;  // off-diagonal
  [[nodiscard]] std::uint64_t row_total(std::uint32_t s) const;
};

// Adds the pairs of `table` to `counts` (sized for `states` when empty). false after
// reporting errors (missing columns, unknown state names).
bool read_noise_labels(const CsvTable& table, const std::vector<std::string>& states,
                       NoiseCounts& counts, DiagnosticEngine& diagnostics);

struct SymmetricNoiseFit {
  double sigma = 0.0;  // P(observed != true)
  Interval interval;   // Wilson, 95%
  std::uint64_t wrong = 0;
  std::uint64_t total = 0;
};

// Requires counts.total() > 0 and num_states >= 2.
SymmetricNoiseFit fit_symmetric_noise(const NoiseCounts& counts);

struct ConfusionFit {
  std::vector<double> matrix;       // [S * S] row-major, rows sum to 1
  std::vector<Interval> intervals;  // [S * S] Wilson per entry (rows without pairs: the
                                    // symmetric fit's interval on the diagonal, 0..1 elsewhere)
  std::vector<std::uint32_t> rows_without_pairs;
};

// Requires counts.total() > 0 and num_states >= 2.
ConfusionFit fit_confusion(const NoiseCounts& counts, double pseudo_count = 0.0);

}  // namespace oasis::fit
