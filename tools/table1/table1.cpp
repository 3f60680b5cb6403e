#include "table1/table1.hpp"

#include <utility>

#include "fit/forward_algorithm.hpp"
#include "fit/switching_fit.hpp"
#include "metrics/context_metrics.hpp"
#include "oasis/rt/attention_filter.hpp"
#include "oasis/rt/catalog_validation.hpp"
#include "oasis/rt/hedged_filter.hpp"

namespace oasis::table1 {
namespace {

rt::FilterOptions filter_options(FilterKind filter, std::uint64_t seed) {
  rt::FilterOptions options;
  options.tie_rule = rt::TieRule::kRandom;
  options.seed = seed;
  switch (filter) {
    case FilterKind::kPaper:
      break;
    case FilterKind::kKeep:
      options.tie_rule = rt::TieRule::kKeep;
      break;
    case FilterKind::kGuard:
      options.zero_likelihood_guard = true;
      break;
    case FilterKind::kSoft:
      options.detection_epsilon = 0.05;
      break;
    case FilterKind::kRobust:
    case FilterKind::kHedged:  // its robust part; the hedge sets the mode itself
      options.mode = rt::FilterMode::kJoint;
      break;
  }
  return options;
}

rt::RewardSource reward_source_of(NoiseReading declared) {
  return declared == NoiseReading::kObserved ? rt::RewardSource::kTrueState
                                             : rt::RewardSource::kObservedState;
}

// The robust or paper filter, or the hedge of both, behind the three calls a trial makes.
class TrialFilter {
 public:
  TrialFilter(const rt::CatalogView& catalog, const TrialSpec& spec) {
    const rt::FilterOptions options = filter_options(spec.filter, spec.seed);
    if (spec.filter == FilterKind::kHedged) {
      rt::HedgeOptions hedge;
      hedge.paper = filter_options(FilterKind::kPaper, spec.seed);
      hedge.robust = options;
      workspace_.resize(rt::HedgedFilter::workspace_size(catalog, hedge));
      hedged_.emplace(catalog, hedge, workspace_.data(), workspace_.size());
    } else {
      workspace_.resize(rt::AttentionFilter::workspace_size(catalog, options));
      single_.emplace(catalog, options, workspace_.data(), workspace_.size());
    }
  }
  rt::FilterError error() const { return hedged_ ? hedged_->error() : single_->error(); }
  void start(std::uint32_t observed) {
    if (hedged_)
      hedged_->start(observed);
    else
      single_->start(observed);
  }
  rt::StepStatus step(std::uint32_t observed, double reward, std::uint32_t action) {
    return hedged_ ? hedged_->step(observed, reward, action)
                   : single_->step(observed, reward, action);
  }
  std::uint32_t ml_abstraction() const {
    return hedged_ ? hedged_->ml_abstraction() : single_->ml_abstraction();
  }

 private:
  std::vector<double> workspace_;
  std::optional<rt::AttentionFilter> single_;
  std::optional<rt::HedgedFilter> hedged_;
};

// R^c(s) for every state s under context c.
std::vector<double> state_rewards(const rt::CatalogView& catalog, std::uint32_t context) {
  const rt::AbstractionView& abstraction = catalog.abstractions[context];
  std::vector<double> rewards(catalog.num_states);
  for (std::uint32_t s = 0; s < catalog.num_states; ++s)
    rewards[s] = abstraction.block_reward[abstraction.block_of[s]];
  return rewards;
}

std::uint32_t random_enabled_action(const rt::TransitionsCsr& csr, std::uint32_t state,
                                    std::uint32_t num_actions, SeededRandom& rng) {
  std::uint32_t enabled = 0;
  for (std::uint32_t a = 0; a < num_actions; ++a) {
    const std::size_t row = static_cast<std::size_t>(state) * num_actions + a;
    if (csr.choice_begin[row + 1] > csr.choice_begin[row]) ++enabled;
  }
  if (enabled == 0) return rt::kNoAction;
  std::uint32_t pick = rng.below(enabled);
  for (std::uint32_t a = 0; a < num_actions; ++a) {
    const std::size_t row = static_cast<std::size_t>(state) * num_actions + a;
    if (csr.choice_begin[row + 1] == csr.choice_begin[row]) continue;
    if (pick == 0) return a;
    --pick;
  }
  return rt::kNoAction;
}

std::uint32_t sample_successor(const rt::TransitionsCsr& csr, std::uint32_t state,
                               std::uint32_t action, std::uint32_t num_actions, SeededRandom& rng) {
  const std::size_t row = static_cast<std::size_t>(state) * num_actions + action;
  const std::uint32_t begin = csr.choice_begin[row];
  const std::uint32_t end = csr.choice_begin[row + 1];
  double u = rng.uniform();
  for (std::uint32_t e = begin; e < end; ++e) {
    u -= csr.probability[e];
    if (u < 0.0) return csr.target[e];
  }
  return csr.target[end - 1];  // rounding: the last edge
}

// Tags that make the environment streams independent of each other.
enum StreamTag : std::uint64_t { kPatternStream = 1, kDynamicsStream = 2, kNoiseStream = 3 };

std::uint64_t environment_seed(const TrialSpec& spec, StreamTag stream) {
  const std::uint64_t tag = (static_cast<std::uint64_t>(spec.pattern) << 16) ^
                            (static_cast<std::uint64_t>(spec.noise) << 8) ^ stream;
  return derive_seed(spec.seed, tag);
}

}  // namespace

std::string_view filter_name(FilterKind filter) {
  switch (filter) {
    case FilterKind::kPaper:
      return "paper";
    case FilterKind::kKeep:
      return "keep";
    case FilterKind::kGuard:
      return "guard";
    case FilterKind::kSoft:
      return "soft";
    case FilterKind::kRobust:
      return "robust";
    case FilterKind::kHedged:
      return "hedged";
  }
  return "?";
}

bool uses_declared_model(FilterKind filter) {
  return filter == FilterKind::kRobust || filter == FilterKind::kHedged;
}

std::optional<FilterKind> parse_filter(std::string_view name) {
  for (FilterKind filter : kAllFilters)
    if (filter_name(filter) == name) return filter;
  return std::nullopt;
}

const std::vector<TransitionModel>& table1_models() {
  static const std::vector<TransitionModel> models{{"i", 0.8}, {"ii", 0.5}};
  return models;
}

Table1Experiment::Table1Experiment(model::ExplicitModel model, std::uint64_t spec_hash)
    : model_(std::move(model)), spec_hash_(spec_hash) {
  abstractions_ =
      pipeline::abstract_contexts(model_, pipeline::all_contexts(model_), {}, abstraction_error_);
}

std::optional<model::CatalogData> Table1Experiment::catalog_for(const TrialSpec& spec,
                                                                std::string& error) const {
  if (!abstractions_) {
    error = abstraction_error_;
    return std::nullopt;
  }
  pipeline::CatalogOptions options;
  options.p_correct = spec.noise == NoiseReading::kNone ? 1.0 : 1.0 - spec.sigma;
  std::optional<model::CatalogData> catalog =
      pipeline::catalog_data(model_, *abstractions_, spec_hash_, options, error);
  if (!catalog) return std::nullopt;
  const std::size_t n = catalog->abstractions.size();
  if (n < 2) {
    error = "the model has fewer than two contexts";
    return std::nullopt;
  }
  catalog->switching.assign(n * n, (1.0 - spec.model.p_stay) / static_cast<double>(n - 1));
  for (std::size_t i = 0; i < n; ++i)
    catalog->switching[i * n + i] = spec.model.p_stay;
  return catalog;
}

std::optional<Trace> Table1Experiment::run_trial(const TrialSpec& spec, std::string& error) const {
  std::optional<model::CatalogData> data = catalog_for(spec, error);
  if (!data) return std::nullopt;
  rt::CatalogView catalog = data->view();
  catalog.observation.reward_source = reward_source_of(spec.declared);
  std::string why;
  if (!rt::validate(catalog, &why)) {
    error = "catalog does not validate: " + why;
    return std::nullopt;
  }
  TrialFilter filter(catalog, spec);
  if (filter.error() != rt::FilterError::kNone) {
    error = "the filter refused the catalog (error " +
            std::to_string(static_cast<std::uint32_t>(filter.error())) + ")";
    return std::nullopt;
  }

  const std::uint32_t n = catalog.num_abstractions;
  const std::uint32_t num_actions = catalog.num_actions;
  std::vector<std::vector<double>> rewards;
  for (std::uint32_t c = 0; c < n; ++c)
    rewards.push_back(state_rewards(catalog, c));

  SeededRandom pattern_rng(environment_seed(spec, kPatternStream));
  SeededRandom dynamics_rng(environment_seed(spec, kDynamicsStream));
  SeededRandom noise_rng(environment_seed(spec, kNoiseStream));
  const double sigma = spec.noise == NoiseReading::kNone ? 0.0 : spec.sigma;

  Trace trace;
  trace.truth = context_sequence(spec.pattern, spec.steps, n, pattern_rng, spec.pattern_options);
  std::uint32_t state = dynamics_rng.below(catalog.num_states);
  {
    const std::uint32_t first_context = trace.truth.empty() ? 0 : trace.truth[0];
    const Sensed sensed = sense(spec.noise, sigma, state, rewards[first_context], noise_rng);
    state = sensed.true_state;
    filter.start(sensed.observed_state);
  }
  for (std::uint32_t k = 0; k < spec.steps; ++k) {
    const std::uint32_t context = trace.truth[k];
    const rt::TransitionsCsr& moves = catalog.abstractions[context].state_transitions;
    const std::uint32_t action = random_enabled_action(moves, state, num_actions, dynamics_rng);
    if (action == rt::kNoAction) {
      error = "no action is enabled in state " + std::to_string(state);
      return std::nullopt;
    }
    state = sample_successor(moves, state, action, num_actions, dynamics_rng);
    const Sensed sensed = sense(spec.noise, sigma, state, rewards[context], noise_rng);
    state = sensed.true_state;
    if (filter.step(sensed.observed_state, sensed.reward, action) ==
        rt::StepStatus::kZeroLikelihood)
      ++trace.zero_likelihood_steps;
    trace.inferred.push_back(filter.ml_abstraction());
    trace.true_state.push_back(state);
    trace.observed_state.push_back(sensed.observed_state);
    trace.reward.push_back(sensed.reward);
    trace.action.push_back(action);
  }
  return trace;
}

std::vector<std::pair<FilterKind, NoiseReading>> filter_columns(const Table1Options& options) {
  std::vector<std::pair<FilterKind, NoiseReading>> columns;
  for (FilterKind filter : options.filters) {
    if (!uses_declared_model(filter)) {
      columns.emplace_back(filter, NoiseReading::kNone);
      continue;
    }
    for (NoiseReading declared : options.declared)
      columns.emplace_back(filter, declared);
  }
  return columns;
}

std::optional<double> fitted_p_stay(const Table1Experiment& experiment, Pattern pattern,
                                    NoiseReading noise, const Table1Options& options,
                                    std::string& error) {
  TrialSpec spec;
  spec.pattern = pattern;
  spec.noise = noise;
  spec.sigma = options.sigma;
  spec.steps = options.steps;
  std::vector<fit::LoggedRun> runs;
  for (std::uint32_t k = 0; k < options.fit_runs; ++k) {
    spec.seed = 10000 + k;
    const std::optional<Trace> trace = experiment.run_trial(spec, error);
    if (!trace) return std::nullopt;
    fit::LoggedRun run;
    for (std::size_t step = 0; step < trace->observed_state.size(); ++step)
      run.steps.push_back({trace->observed_state[step], trace->reward[step], trace->action[step]});
    runs.push_back(std::move(run));
  }
  const std::optional<model::CatalogData> catalog = experiment.catalog_for(spec, error);
  if (!catalog) return std::nullopt;
  fit::FilterModel model = fit::filter_model(*catalog, experiment.model());
  if (noise != NoiseReading::kNone) {
    model.noise.kind = fit::StateNoise::Kind::kSymmetric;
    model.noise.p_correct = 1.0 - options.sigma;
    model.noise.reward = noise == NoiseReading::kObserved ? fit::RewardFollows::kTrueState
                                                          : fit::RewardFollows::kObservedState;
  }
  const std::optional<fit::SwitchingFit> fitted = fit::fit_switching(model, runs, {}, error);
  if (!fitted) return std::nullopt;
  return fitted->p_stay;
}

std::optional<std::vector<RowResult>> run_table1(const Table1Experiment& experiment,
                                                 const Table1Options& options, std::string& error,
                                                 const TraceSink& sink) {
  std::vector<RowResult> rows;
  std::vector<TransitionModel> models = table1_models();
  if (options.fit_runs > 0) models.push_back({"fit", 0.0});
  for (const TransitionModel& listed : models) {
    for (Pattern pattern : options.patterns) {
      std::vector<NoiseReading> noises{NoiseReading::kNone};
      if (pattern_is_noisy(pattern)) noises = options.noises;
      for (NoiseReading noise : noises) {
        TransitionModel model = listed;
        if (model.id == "fit") {
          const std::optional<double> p_stay =
              fitted_p_stay(experiment, pattern, noise, options, error);
          if (!p_stay) return std::nullopt;
          model.p_stay = *p_stay;
        }
        for (const auto& [filter, declared] : filter_columns(options)) {
          std::vector<double> accuracy, avg_lag, max_lag, zero;
          for (std::uint32_t seed = 0; seed < options.seeds; ++seed) {
            TrialSpec spec;
            spec.model = model;
            spec.pattern = pattern;
            spec.noise = noise;
            spec.sigma = options.sigma;
            spec.filter = filter;
            if (declared != NoiseReading::kNone) spec.declared = declared;
            spec.seed = seed;
            spec.steps = options.steps;
            const std::optional<Trace> trace = experiment.run_trial(spec, error);
            if (!trace) return std::nullopt;
            const metrics::TrialMetrics trial =
                metrics::trial_metrics(trace->truth, trace->inferred);
            accuracy.push_back(trial.accuracy);
            avg_lag.push_back(trial.avg_lag);
            max_lag.push_back(trial.max_lag);
            zero.push_back(trace->zero_likelihood_steps);
            if (sink) sink(spec, *trace);
          }
          rows.push_back({model.id, pattern, noise, filter, declared, model.p_stay,
                          metrics::mean_std(accuracy), metrics::mean_std(avg_lag),
                          metrics::mean_std(max_lag), metrics::mean_std(zero)});
        }
      }
    }
  }
  return rows;
}

}  // namespace oasis::table1
