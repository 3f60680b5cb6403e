#pragma once
// The experiment of Table I (the paper's discrete-space tracking example), run on the catalog
// that pipeline/discrete_catalog.hpp compiles from the spec and on the runtime's AttentionFilter.
//
// One trial (seed, transition model, pattern, noise reading, filter):
//  1. the catalog is built from the model with p_correct = 1 - sigma (the robust section; 1
//     for noiseless patterns) and its switching matrix replaced by the transition model's:
//     p(stay) on the diagonal, (1 - p(stay)) / (N - 1) elsewhere;
//  2. the true context follows the pattern (patterns.hpp) for `steps` steps;
//  3. s_0 is drawn uniformly (Algorithm 1, line 1), sensed through the noise reading and given
//     to start(); then at every step k the robot picks an action uniformly among those
//     enabled in the true state (the paper lets the robot "randomly choose its actions"; the
//     filter's action() is not used), the true state moves under the true context's
//     transitions P^c(s' | s, a), the noise reading (noise.hpp) produces the observed state
//     and the reward r = R^c(.), and step(observed, r, a) is called;
//  4. the ML abstraction after step k is the inferred context at k; the statistics are
//     metrics/context_metrics.hpp's.
// The environment's random numbers depend on (seed, pattern, noise) only: every filter and
// both transition models see the same true contexts, states and noise for a given seed.
// The filter's own tie-breaking PRNG is seeded with the seed.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "metrics/mean_std.hpp"
#include "model/explicit_model.hpp"
#include "pipeline/discrete_catalog.hpp"
#include "table1/noise.hpp"
#include "table1/patterns.hpp"

namespace oasis::table1 {

// The filters compared. `paper` is Algorithm 1 with random tie-breaking (TieRule::kRandom);
// the others change one thing each with respect to it:
//  keep   - TieRule::kKeep (keep the current ML abstraction when tied, else the lowest index);
//  guard  - zero_likelihood_guard (keep the prediction instead of resetting to the prior when
//           no abstraction explains the observation);
//  soft   - detection_epsilon = 0.05 (soft detection model);
//  robust - FilterMode::kJoint (joint belief over abstraction and true state, observation
//           model p_correct = 1 - sigma, the reward following the state the declared reading
//           says), random ties;
//  hedged - rt::HedgedFilter: Algorithm 1 and the robust filter of the declared reading,
//           weighed by how well each predicts the rewards.
// The declared reading is the noise the model-based filters assume (TrialSpec::declared):
// `observed` - the reward follows the true state (RewardSource::kTrueState); `perceived` and
// `process` - it follows the observed state (kObservedState). Process noise is not an
// observation model, but to the filter it looks like one whose reward follows what is seen.
enum class FilterKind : std::uint32_t { kPaper, kKeep, kGuard, kSoft, kRobust, kHedged };

inline constexpr FilterKind kAllFilters[] = {FilterKind::kPaper,  FilterKind::kKeep,
                                             FilterKind::kGuard,  FilterKind::kSoft,
                                             FilterKind::kRobust, FilterKind::kHedged};

// True for the filters that run on a declared observation model (robust, hedged).
bool uses_declared_model(FilterKind filter);

std::string_view filter_name(FilterKind filter);
std::optional<FilterKind> parse_filter(std::string_view name);

// The abstraction transition models of Table I.
struct TransitionModel {
  std::string id;  // "i" or "ii"
  double p_stay = 0.8;
};

const std::vector<TransitionModel>& table1_models();

struct TrialSpec {
  TransitionModel model;
  Pattern pattern = Pattern::kStep;
  NoiseReading noise = NoiseReading::kNone;
  double sigma = 0.0;  // used when noise != kNone
  FilterKind filter = FilterKind::kPaper;
  NoiseReading declared = NoiseReading::kObserved;  // robust and hedged filters only
  std::uint64_t seed = 0;
  std::uint32_t steps = 500;
  PatternOptions pattern_options;
};

struct Trace {
  std::vector<std::uint32_t> truth;     // true context at step k
  std::vector<std::uint32_t> inferred;  // ML abstraction after step k
  std::vector<std::uint32_t> true_state;
  std::vector<std::uint32_t> observed_state;
  std::vector<double> reward;
  std::vector<std::uint32_t> action;        // the action taken before step k's observation
  std::uint32_t zero_likelihood_steps = 0;  // steps where step() reported kZeroLikelihood
};

class Table1Experiment {
 public:
  // Keeps a copy of the explored model and abstracts every context once: trials differ only
  // in the catalog's switching model and observation section, not in its abstractions. The
  // model must have at least two contexts.
  Table1Experiment(model::ExplicitModel model, std::uint64_t spec_hash);

  // One trial; nullopt with `error` set if the catalog cannot be built or the filter refuses it.
  std::optional<Trace> run_trial(const TrialSpec& spec, std::string& error) const;

  // The catalog a trial runs on (exposed for the report and the tests).
  std::optional<model::CatalogData> catalog_for(const TrialSpec& spec, std::string& error) const;

  const model::ExplicitModel& model() const { return model_; }

 private:
  model::ExplicitModel model_;
  std::uint64_t spec_hash_ = 0;
  std::optional<std::vector<pipeline::DiscreteAbstraction>> abstractions_;
  std::string abstraction_error_;  // why abstractions_ is empty
};

// One row of the results: a configuration summarised over seeds.
struct RowResult {
  std::string model;  // "i" / "ii"
  Pattern pattern = Pattern::kStep;
  NoiseReading noise = NoiseReading::kNone;
  FilterKind filter = FilterKind::kPaper;
  NoiseReading declared = NoiseReading::kNone;  // kNone for the filters without a model
  double p_stay = 0.0;                          // the transition model's (fitted for "fit")
  metrics::MeanStd accuracy;
  metrics::MeanStd avg_lag;
  metrics::MeanStd max_lag;
  metrics::MeanStd zero_likelihood_steps;
};

struct Table1Options {
  std::uint32_t seeds = 5;  // seeds 0 .. seeds-1
  std::uint32_t steps = 500;
  double sigma = 0.7;
  std::vector<NoiseReading> noises{std::begin(kNoisyReadings), std::end(kNoisyReadings)};
  std::vector<FilterKind> filters{std::begin(kAllFilters), std::end(kAllFilters)};
  std::vector<Pattern> patterns{std::begin(kAllPatterns), std::end(kAllPatterns)};
  // The readings the robust and hedged filters are run with (each is a column).
  std::vector<NoiseReading> declared{NoiseReading::kObserved};
  // > 0: a third transition model, "fit", whose p(stay) is fitted per row (pattern and noise)
  // by maximum likelihood (oasisc fit switching's fit) from this many training runs of the
  // row's own pattern and noise, on seeds the table's trials do not use (10000, 10001, ...).
  // The true contexts follow the pattern, not a Markov chain: the fit finds the p(stay) that
  // explains the pattern best. The training runs' filter is irrelevant (actions are random);
  // the fit assumes the row's own noise reading as the observation model.
  std::uint32_t fit_runs = 0;
};

// The p(stay) fitted for one row from `options.fit_runs` training runs (see fit_runs).
std::optional<double> fitted_p_stay(const Table1Experiment& experiment, Pattern pattern,
                                    NoiseReading noise, const Table1Options& options,
                                    std::string& error);

// The filter columns of a table: every filter, the model-based ones once per declared reading
// (the others with kNone).
std::vector<std::pair<FilterKind, NoiseReading>> filter_columns(const Table1Options& options);

// Called with every trial's spec and trace (for CSV traces and plots).
using TraceSink = std::function<void(const TrialSpec&, const Trace&)>;

// Every (model, pattern, noise, filter) row: noiseless patterns with noise `none`, noisy ones
// with each reading in options.noises. nullopt with `error` set on the first failing trial.
std::optional<std::vector<RowResult>> run_table1(const Table1Experiment& experiment,
                                                 const Table1Options& options, std::string& error,
                                                 const TraceSink& sink = {});

}  // namespace oasis::table1
