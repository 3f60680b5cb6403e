// `oasisc fit switching|noise|depth-noise`: maximum-likelihood fits of the switching model
// and the observation models from logs, each printed with a 95% interval and as a spec
// fragment to paste (docs/fitting.md).

#include <chrono>
#include <cstdio>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

#include <unistd.h>

#include "cli/commands.hpp"
#include "command_line/number_options.hpp"
#include "fit/csv_table.hpp"
#include "fit/depth_noise_fit.hpp"
#include "fit/forward_algorithm.hpp"
#include "fit/noise_fit.hpp"
#include "fit/spec_fragment.hpp"
#include "fit/switching_fit.hpp"
#include "fit/switching_log.hpp"
#include "frontend/lexer.hpp"
#include "pipeline/discrete_catalog.hpp"
#include "support/atomic_file.hpp"
#include "support/error_report.hpp"
#include "text/printable_text.hpp"

namespace oasis::cli {
namespace {

struct SwitchingOptions {
  std::string spec;
  std::vector<std::string> logs;
  bool full = false;
  double detection_epsilon = 0.001;  // bias of p_stay about +epsilon (docs/fitting.md)
  double reward_tolerance = 1e-9;
  std::optional<double> state_noise;
  std::optional<std::string> reward_follows;  // default: the spec's, else "true"
  bool paper = false;
  std::string output;
  CommonOptions common;
};

struct NoiseOptions {
  std::string spec;
  std::vector<std::string> labels;
  bool matrix = false;
  double pseudo_count = 0.0;
  std::string reward_follows = "true";
  std::string output;
  CommonOptions common;
};

struct DepthOptions {
  std::vector<std::string> calibration;
  std::uint32_t degree = 2;
  std::string bias = "constant";
  std::vector<double> at;
  std::string object = "human1";
  std::vector<std::string> variables{"x1", "y1"};
  std::string output;
  std::size_t max_errors = 20;
};

std::string fixed(double value, int digits = 4) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(digits) << value;
  return out.str();
}

std::string interval_text(const fit::Interval& interval, int digits = 4) {
  return "[" + fixed(interval.low, digits) + ", " + fixed(interval.high, digits) + "]";
}

std::string files_text(std::size_t count) {
  return std::to_string(count) + (count == 1 ? " file" : " files");
}

// Prints the fragment and writes it to `path` when one is given ("-": standard output,
// where it already is). false on a write error.
bool deliver_fragment(const std::string& fragment, const std::string& path) {
  std::cout << '\n' << fragment;
  if (path.empty() || path == "-") return true;
  std::string error;
  if (!write_atomically(path, fragment, error)) {
    report_error(path, error);
    return false;
  }
  std::cout << "wrote " << path << '\n';
  return true;
}

// A spec that must be discrete, and its catalog compiled in memory.
struct CompiledSpec {
  std::optional<LoadedModel> loaded;
  std::optional<model::CatalogData> catalog;
};

std::optional<CompiledSpec> compile_spec(const std::string& path, const CommonOptions& common,
                                         SourceManager& sources, DiagnosticEngine& diagnostics) {
  CompiledSpec out;
  out.loaded = load_model(path, sources, diagnostics, effective_load_options(common));
  if (!out.loaded || diagnostics.has_errors()) return std::nullopt;
  if (!out.loaded->model) {
    report_error(path,
                 "the discrete fits need explicit states; this is a continuous spec (its depth "
                 "noise is fitted by 'oasisc fit depth-noise')");
    return std::nullopt;
  }
  std::string error;
  out.catalog = pipeline::build_catalog(*out.loaded->model, out.loaded->source_hash, {}, error);
  if (!out.catalog) {
    report_error(path, error);
    return std::nullopt;
  }
  return out;
}

// Progress on stderr at most five times a second.
class Progress {
 public:
  explicit Progress(bool enabled) : enabled_(enabled) {}
  ~Progress() {
    if (shown_) std::fputc('\n', stderr);
  }
  void report(std::size_t evaluation, double log_likelihood) {
    if (!enabled_) return;
    const auto now = std::chrono::steady_clock::now();
    if (shown_ && now - last_ < std::chrono::milliseconds(200)) return;
    last_ = now;
    shown_ = true;
    std::fprintf(stderr, "\roasisc: fit: evaluation %zu, log-likelihood %.4f   ", evaluation,
                 log_likelihood);
    std::fflush(stderr);
  }

 private:
  bool enabled_;
  bool shown_ = false;
  std::chrono::steady_clock::time_point last_;
};

int run_switching(const SwitchingOptions& options) {
  SourceManager sources;
  DiagnosticEngine diagnostics(sources, std::cerr, options.common.max_errors);
  auto compiled = compile_spec(options.spec, options.common, sources, diagnostics);
  if (!compiled) return 1;
  const model::CatalogData& catalog = *compiled->catalog;
  const model::ExplicitModel& model = *compiled->loaded->model;

  fit::LogNames names{catalog.state_names, catalog.action_names};
  std::vector<fit::LoggedRun> runs;
  for (const std::string& path : options.logs) {
    if (diagnostics.should_stop()) break;
    const auto table = fit::read_csv(path, sources, diagnostics,
                                     {.max_bytes = options.common.load.max_input_bytes});
    if (table) fit::read_switching_log(*table, names, runs, diagnostics);
  }
  if (diagnostics.has_errors()) return 1;

  fit::FilterModel filter = fit::filter_model(catalog, model);
  filter.detection_epsilon = options.detection_epsilon;
  filter.reward_tolerance = options.reward_tolerance;
  std::string noise_source;
  if (options.state_noise) {
    filter.noise.kind = fit::StateNoise::Kind::kSymmetric;
    filter.noise.p_correct = 1.0 - *options.state_noise;
    noise_source = "--state-noise";
  } else if (!options.paper && catalog.observation == rt::ObservationKind::kSymmetric) {
    filter.noise.kind = fit::StateNoise::Kind::kSymmetric;
    filter.noise.p_correct = catalog.p_correct;
    noise_source = "the spec";
  } else if (!options.paper && catalog.observation == rt::ObservationKind::kMatrix) {
    filter.noise.kind = fit::StateNoise::Kind::kMatrix;
    filter.noise.confusion = catalog.confusion;
    noise_source = "the spec";
  }
  const bool spec_says_observed = catalog.observation != rt::ObservationKind::kNone &&
                                  catalog.reward_source == rt::RewardSource::kObservedState;
  const bool reward_observed =
      options.reward_follows ? *options.reward_follows == "observed" : spec_says_observed;
  filter.noise.reward =
      reward_observed ? fit::RewardFollows::kObservedState : fit::RewardFollows::kTrueState;
  if (filter.joint() && catalog.num_states < 2 && filter.noise.p_correct != 1.0) {
    report_error(options.spec, "state noise needs two or more states");
    return 1;
  }

  const bool show = effective_load_options(options.common).progress;
  fit::SwitchingFitOptions fit_options;
  fit_options.full = options.full;
  std::string error;
  std::optional<fit::SwitchingFit> result;
  {
    Progress progress(show);
    fit_options.progress = [&](std::size_t evaluation, double value) {
      progress.report(evaluation, value);
    };
    result = fit::fit_switching(filter, runs, fit_options, error);
  }
  if (!result) {
    report_error(std::string(kProgram) + ": fit switching", error);
    return 1;
  }
  const fit::SwitchingFit& fitted = *result;
  std::vector<std::string> contexts;
  for (const model::AbstractionData& abstraction : catalog.abstractions)
    contexts.push_back(abstraction.context);

  std::cout << "fit switching: " << fitted.runs << (fitted.runs == 1 ? " run, " : " runs, ")
            << fitted.steps << " steps (" << files_text(options.logs.size()) << "), "
            << contexts.size() << " contexts\n";
  if (filter.joint()) {
    std::cout << "likelihood: joint forward algorithm over (abstraction, true state), state "
              << (filter.noise.kind == fit::StateNoise::Kind::kMatrix
                      ? std::string("confusion matrix")
                      : "noise P(observed != true) = " +
                            fit::significant_text(1.0 - filter.noise.p_correct))
              << " (from " << noise_source << "), reward follows the "
              << (reward_observed ? "observed" : "true") << " state, detection epsilon "
              << filter.detection_epsilon << '\n';

  } else {
    std::cout << "likelihood: forward algorithm of Algorithm 1 (observed state taken as true), "
                 "detection epsilon "
              << filter.detection_epsilon << '\n';
  }
  std::cout << "symmetric model: p_stay = " << fixed(fitted.p_stay) << "  95% CI "
            << interval_text(fitted.p_stay_interval) << " (profile likelihood)";
  if (fitted.p_stay_error && *fitted.p_stay_error < 0.5) {
    std::cout << "; standard error " << fixed(*fitted.p_stay_error) << " (observed information)";
  }
  std::cout << '\n';
  if (fitted.p_stay_interval.high - fitted.p_stay_interval.low > 0.5) {
    std::cout << "note: the logs say little about p_stay (a wide interval): log longer runs, or "
                 "runs through states whose reward tells the contexts apart\n";
  }
  if (fitted.full) {
    std::cout << "full model: p(to | from), 95% CI (Wald on the logits' observed information, "
                 "delta method):\n";
    const std::size_t n = contexts.size();
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j) {
        const auto& interval = fitted.entry_intervals[i * n + j];
        std::cout << "  " << contexts[i] << " -> " << contexts[j] << ": "
                  << fixed(fitted.matrix[i * n + j]) << "  "
                  << (interval ? interval_text(*interval) : "(no interval: on the boundary)")
                  << '\n';
      }
  }
  std::cout << "log-likelihood " << fixed(fitted.log_likelihood) << " (" << fitted.optimiser << ", "
            << fitted.evaluations << " evaluations)\n";

  std::string fragment = "// fitted by oasisc fit switching from " + std::to_string(fitted.steps) +
                         " logged steps; paste inside the catalog { } block of " + options.spec +
                         ",\n// replacing its switching model\n";
  fragment += fitted.full ? fit::switching_matrix_fragment(fitted.matrix, contexts)
                          : fit::switching_stay_fragment(fitted.p_stay);
  return deliver_fragment(fragment, options.output) ? 0 : 1;
}

int run_noise(const NoiseOptions& options) {
  SourceManager sources;
  DiagnosticEngine diagnostics(sources, std::cerr, options.common.max_errors);
  auto compiled = compile_spec(options.spec, options.common, sources, diagnostics);
  if (!compiled) return 1;
  const std::vector<std::string>& states = compiled->catalog->state_names;
  if (states.size() < 2) {
    report_error(options.spec, "state noise needs two or more states");
    return 1;
  }
  fit::NoiseCounts counts;
  for (const std::string& path : options.labels) {
    if (diagnostics.should_stop()) break;
    const auto table = fit::read_csv(path, sources, diagnostics,
                                     {.max_bytes = options.common.load.max_input_bytes});
    if (table) fit::read_noise_labels(*table, states, counts, diagnostics);
  }
  if (diagnostics.has_errors()) return 1;
  if (counts.total() == 0) {
    report_error(std::string(kProgram) + ": fit noise", "the labelled logs have no pairs");
    return 1;
  }
  const fit::SymmetricNoiseFit symmetric = fit::fit_symmetric_noise(counts);
  std::cout << "fit noise: " << symmetric.total << " labelled pairs ("
            << files_text(options.labels.size()) << "), " << states.size() << " states\n";
  std::cout << "symmetric model: P(observed != true) = " << fixed(symmetric.sigma) << "  95% CI "
            << interval_text(symmetric.interval) << " (Wilson score; closed-form MLE, "
            << symmetric.wrong << " of " << symmetric.total << " wrong)\n";
  std::cout << "per true state (pairs): ";
  for (std::uint32_t s = 0; s < states.size(); ++s) {
    const std::uint64_t total = counts.row_total(s);
    const std::uint64_t right = counts.counts[static_cast<std::size_t>(s) * states.size() + s];
    std::cout << (s ? ", " : "") << states[s] << " "
              << (total ? fixed(1.0 - static_cast<double>(right) / static_cast<double>(total), 3)
                        : std::string("-"))
              << " (" << total << ")";
  }
  std::cout << '\n';
  std::string fragment = "// fitted by oasisc fit noise from " + std::to_string(symmetric.total) +
                         " labelled pairs; paste inside the catalog { } block of " + options.spec +
                         "\n// ('reward follows' is not in the labels: true or observed, see "
                         "docs/fitting.md)\n";
  if (options.matrix) {
    const fit::ConfusionFit confusion = fit::fit_confusion(counts, options.pseudo_count);
    std::cout << "confusion matrix p(observed | true), 95% CI (Wilson score per entry"
              << (options.pseudo_count > 0 ? ", pseudo-count " + fixed(options.pseudo_count, 2)
                                           : std::string())
              << "):\n";
    for (std::uint32_t s = 0; s < states.size(); ++s)
      for (std::uint32_t o = 0; o < states.size(); ++o) {
        const std::size_t k = static_cast<std::size_t>(s) * states.size() + o;
        std::cout << "  " << states[s] << " -> " << states[o] << ": " << fixed(confusion.matrix[k])
                  << "  " << interval_text(confusion.intervals[k]) << '\n';
      }
    for (std::uint32_t s : confusion.rows_without_pairs)
      report_warning(
          std::string(kProgram) + ": fit noise",
          "no pairs with true state " + states[s] + ": its row is the symmetric estimate");
    fragment += fit::confusion_fragment(confusion.matrix, states, options.reward_follows);
  } else {
    fragment += fit::state_noise_fragment(symmetric.sigma, options.reward_follows);
  }
  return deliver_fragment(fragment, options.output) ? 0 : 1;
}

std::string polynomial_text(const std::vector<double>& c, const char* variable) {
  std::string out = fit::significant_text(c.empty() ? 0.0 : c[0]);
  for (std::size_t k = 1; k < c.size(); ++k) {
    out += c[k] < 0 ? " - " : " + ";
    out += fit::significant_text(std::fabs(c[k])) + "*" + variable;
    if (k == 2) out += "^2";
  }
  return out;
}

int run_depth(const DepthOptions& options) {
  SourceManager sources;
  DiagnosticEngine diagnostics(sources, std::cerr, options.max_errors);
  std::vector<fit::DepthPair> pairs;
  for (const std::string& path : options.calibration) {
    if (diagnostics.should_stop()) break;
    const auto table = fit::read_csv(path, sources, diagnostics);
    if (table) fit::read_calibration(*table, pairs, diagnostics);
  }
  if (diagnostics.has_errors()) return 1;
  fit::DepthNoiseOptions fit_options;
  fit_options.degree = options.degree;
  fit_options.bias = options.bias == "none"     ? fit::DepthBias::kNone
                     : options.bias == "linear" ? fit::DepthBias::kLinear
                                                : fit::DepthBias::kConstant;
  std::string error;
  const auto fitted = fit::fit_depth_noise(pairs, fit_options, error);
  if (!fitted) {
    report_error(std::string(kProgram) + ": fit depth-noise", error);
    return 1;
  }
  std::cout << "fit depth-noise: " << fitted->pairs << " pairs ("
            << files_text(options.calibration.size()) << "), " << fitted->distinct_distances
            << " distinct true distances in [" << fitted->range_low << ", " << fitted->range_high
            << "] m\n";
  std::cout << "model: measured = true + bias(d) + sigma(d) * e, e ~ N(0, 1); sigma(d) = "
            << (options.degree == 0   ? "a"
                : options.degree == 1 ? "a + b*d"
                                      : "a + b*d + c*d^2")
            << ", bias(d) = "
            << (fit_options.bias == fit::DepthBias::kNone       ? "0"
                : fit_options.bias == fit::DepthBias::kConstant ? "b0"
                                                                : "b0 + b1*d")
            << "; " << fitted->optimiser << ", " << fitted->evaluations << " evaluations\n";
  std::cout << "estimates, 95% CI (Wald, observed information):\n";
  const char* bias_names[] = {"b0", "b1"};
  const char* sigma_names[] = {"a", "b", "c"};
  const std::size_t nb = fitted->bias.size();
  for (std::size_t j = 0; j < nb + fitted->sigma.size(); ++j) {
    const double value = j < nb ? fitted->bias[j] : fitted->sigma[j - nb];
    std::cout << "  " << std::left << std::setw(3) << (j < nb ? bias_names[j] : sigma_names[j - nb])
              << std::right << "= " << std::setw(11) << fit::significant_text(value, 5) << "  "
              << (fitted->intervals.empty()
                      ? std::string("(no interval)")
                      : "[" + fit::significant_text(fitted->intervals[j].low, 5) + ", " +
                            fit::significant_text(fitted->intervals[j].high, 5) + "]")
              << '\n';
  }
  if (fitted->floor_active)
    std::cout << "note: sigma(d) reaches 0 on the data's range: the constraint sigma(d) > 0 is "
                 "active, no interval is given\n";
  std::vector<double> at = options.at;
  if (at.empty())
    for (int k = 0; k <= 4; ++k)
      at.push_back(fitted->range_low + (fitted->range_high - fitted->range_low) * k / 4.0);
  std::cout << "sigma(d), 95% CI (delta method):\n";
  for (double d : at) {
    const auto interval = fitted->sigma_interval(d);
    std::cout << "  d = " << fit::significant_text(d, 4)
              << " m: " << fit::significant_text(fitted->sigma_at(d), 4) << " m"
              << (interval ? "  [" + fit::significant_text(interval->low, 4) + ", " +
                                 fit::significant_text(interval->high, 4) + "]"
                           : std::string())
              << ((d < fitted->range_low || d > fitted->range_high) ? "  (extrapolated)" : "")
              << '\n';
  }
  std::cout << "log-likelihood " << fixed(fitted->log_likelihood) << '\n';

  std::ostringstream range;
  range << "d in [" << fitted->range_low << ", " << fitted->range_high << "] m";
  std::string fragment =
      "// fitted by oasisc fit depth-noise from " + std::to_string(fitted->pairs) + " pairs, " +
      range.str() +
      " (valid on that range);\n// paste into the catalog's observation block "
      "(docs/spec-language.md):\n" +
      fit::object_noise_fragment(options.object, options.variables, fitted->sigma);
  if (!fitted->bias.empty()) {
    fragment += "// bias: measured - true = " + polynomial_text(fitted->bias, "d") +
                " m (subtract it in perception; the observation model has no bias)\n";
  }
  return deliver_fragment(fragment, options.output) ? 0 : 1;
}

// Every fit's -o: where deliver_fragment() also writes the spec fragment.
// A name the fragment declares (--object, --variables): one identifier of the spec language,
// so that the printed fragment can never carry text that `check` would read as more spec.
CLI::Validator spec_identifier() {
  return CLI::Validator(
      [](std::string& value) -> std::string {
        if (frontend::is_identifier(value)) return {};
        return "\"" + text::printable_excerpt(value) +
               "\" is not a name of the spec language (a letter or '_', then letters, digits "
               "or '_'; not a keyword)";
      },
      "NAME");
}

void add_fragment_output(CLI::App& fit, std::string& path) {
  fit.add_option(
      "-o,--output", path,
      "Also write the spec fragment to this file (-: only the standard output it is printed on)");
}

}  // namespace

CommandRunner add_fit_command(CLI::App& app) {
  CLI::App* command = app.add_subcommand(
      "fit",
      "Maximum-likelihood fits from logs: the switching model, the state noise, the depth "
      "noise sigma(d)");
  command->require_subcommand(1);
  command->footer(
      "Each fit prints its estimate with a 95% confidence interval and a spec fragment to\n"
      "paste. Input formats and methods: docs/fitting.md.");

  auto switching = std::make_shared<SwitchingOptions>();
  CLI::App* sw = command->add_subcommand(
      "switching",
      "Fit p_stay (or --full, the whole switching matrix) from logged runs by "
      "maximising the filter's marginal likelihood");
  sw->add_option("spec", switching->spec, "Discrete spec (.oasis)")->required();
  sw->add_option("logs", switching->logs,
                 "CSV logs: run,step,action,observed_state,reward (or oasis-sim traces)")
      ->required();
  sw->add_flag("--full", switching->full, "Fit the full N x N switching matrix too");
  sw->add_option("--detection-epsilon", switching->detection_epsilon,
                 "Soft detection model: p(r | phi, s) = epsilon when r != R(s)")
      ->capture_default_str()
      ->check(real_in(closed(0.0, 0.5)));
  sw->add_option("--reward-tolerance", switching->reward_tolerance,
                 "A logged reward matches R(s) within this absolute tolerance")
      ->capture_default_str()
      ->check(real_in(non_negative()));
  sw->add_option("--state-noise", switching->state_noise,
                 "Symmetric state noise P(observed != true): use the joint forward algorithm")
      ->check(real_in(closed(0.0, 1.0)));
  sw->add_option("--reward-follows", switching->reward_follows,
                 "With state noise: the reward belongs to the true or the observed state "
                 "(default: the spec's observation block, else true)")
      ->check(CLI::IsMember({"true", "observed"}));
  sw->add_flag("--paper", switching->paper,
               "Ignore the spec's observation model: Algorithm 1's likelihood");
  add_fragment_output(*sw, switching->output);
  add_common_options(*sw, switching->common);
  sw->footer(
      "Examples:\n"
      "  oasisc fit switching specs/discrete_tracking.oasis logs/run*.csv\n"
      "  oasisc fit switching specs/discrete_tracking.oasis log.csv --state-noise 0.3 --full");

  auto noise = std::make_shared<NoiseOptions>();
  CLI::App* ns = command->add_subcommand(
      "noise",
      "Fit the discrete state noise (or --matrix, a confusion matrix) from labelled "
      "(true_state, observed_state) pairs");
  ns->add_option("spec", noise->spec, "Discrete spec (.oasis), for the state names")->required();
  ns->add_option("labels", noise->labels, "CSV files with columns true_state,observed_state")
      ->required();
  ns->add_flag("--matrix", noise->matrix, "Fit the full confusion matrix p(observed | true)");
  ns->add_option("--pseudo-count", noise->pseudo_count,
                 "--matrix: add this to every count (not the MLE; unseen confusions stay "
                 "possible; at most 10^6, beyond which it outweighs any data)")
      ->capture_default_str()
      ->check(real_in(non_negative(1e6)));
  ns->add_option("--reward-follows", noise->reward_follows,
                 "What the fragment declares: the reward belongs to the true or observed state")
      ->capture_default_str()
      ->check(CLI::IsMember({"true", "observed"}));
  add_fragment_output(*ns, noise->output);
  add_common_options(*ns, noise->common);

  auto depth = std::make_shared<DepthOptions>();
  CLI::App* dn = command->add_subcommand(
      "depth-noise", "Fit sigma(d) = a + b*d + c*d^2 from (true_m, measured_m) calibration pairs");
  dn->add_option("calibration", depth->calibration, "CSV files with columns true_m,measured_m")
      ->required();
  dn->add_option("--degree", depth->degree, "Degree of sigma(d): 0, 1 or 2")
      ->capture_default_str()
      ->check(whole_in(0, 2));
  dn->add_option("--bias", depth->bias,
                 "Mean error of a measurement: none, constant (b0) or linear (b0 + b1*d)")
      ->capture_default_str()
      ->check(CLI::IsMember({"none", "constant", "linear"}));
  dn->add_option("--at", depth->at, "Distances (m) at which to print sigma(d) with its interval")
      ->delimiter(',')
      ->check(real_in(non_negative(1000.0)));
  dn->add_option("--object", depth->object, "The object the fragment declares")
      ->capture_default_str()
      ->check(spec_identifier());
  dn->add_option("--variables", depth->variables,
                 "The continuous variables the object's position is (comma-separated)")
      ->delimiter(',')
      ->capture_default_str()
      ->check(spec_identifier());
  add_fragment_output(*dn, depth->output);
  dn->add_option("--max-errors", depth->max_errors, "Stop after this many errors")
      ->capture_default_str()
      ->check(whole_in(1, 100000));

  return [command, sw, ns, switching, noise, depth] {
    if (command->got_subcommand(sw)) return run_switching(*switching);
    if (command->got_subcommand(ns)) return run_noise(*noise);
    return run_depth(*depth);
  };
}

}  // namespace oasis::cli
