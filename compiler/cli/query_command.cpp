// `oasisc query MODEL --prop '...' [--props FILE]`: answer PRISM properties on a model, each
// on one line, exactly (rationals) or with a sound interval (docs/properties.md).

#include <algorithm>
#include <iostream>
#include <memory>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "command_line/number_options.hpp"
#include "property/evaluator.hpp"
#include "property/parser.hpp"
#include "property/quotient_solve.hpp"
#include "support/atomic_file.hpp"
#include "support/error_report.hpp"
#include "support/input_validation.hpp"
#include "support/mapped_file.hpp"
#include "support/text.hpp"

namespace oasis::cli {
namespace {

// An exact answer is printed as its fraction up to this many characters; past it, in
// scientific form with its length (a fraction of megabytes helps nobody on a terminal).
constexpr std::size_t kMaxPrintedFraction = 2000;

struct QueryOptions {
  std::string model;
  std::vector<std::string> props;       // --prop texts
  std::vector<std::string> prop_files;  // --props files
  std::string mode = "auto";
  double precision = 1e-6;
  bool bisimulation = false;
  bool whole_fractions = false;  // --whole-fractions
  std::string scheduler_path;    // --scheduler
  CommonOptions common;
};

// The properties of every --props file and --prop text, each parsed into its own file of
// `sources` (a --prop is named "--prop N" in messages).
std::vector<property::PropertiesFile> read_properties(const QueryOptions& options,
                                                      SourceManager& sources,
                                                      DiagnosticEngine& diagnostics) {
  std::vector<property::PropertiesFile> files;
  for (const std::string& path : options.prop_files) {
    MappedFile contents;
    std::string reason;
    if (!contents.open(path, options.common.load.max_spec_bytes, reason)) {
      diagnostics.file_error(path, "cannot read the properties: " + reason);
      continue;
    }
    const FileId file = sources.add(path, std::move(contents));
    if (validate_input(file, diagnostics)) files.push_back(property::parse_file(file, diagnostics));
  }
  for (std::size_t i = 0; i < options.props.size(); ++i) {
    const FileId file = sources.add("--prop " + std::to_string(i + 1), options.props[i]);
    if (validate_input(file, diagnostics)) files.push_back(property::parse_file(file, diagnostics));
  }
  return files;
}

// The reward structures the properties name, for the loader (--rewards): all of them when one
// says only R (PRISM's first structure).
std::string rewards_used(const std::vector<property::PropertiesFile>& files) {
  std::set<std::string> names;
  for (const property::PropertiesFile& file : files) {
    for (const property::Extension& node : file.extensions) {
      const auto* q = std::get_if<property::Quantifier>(&node);
      if (q == nullptr || !q->reward) continue;
      if (!q->reward_name) return "all";
      names.insert(*q->reward_name);
    }
  }
  if (names.empty()) return "none";
  std::string list;
  for (const std::string& name : names)
    list += (list.empty() ? "" : ",") + name;
  return list;
}

std::string value_text(const modelcheck::Value& value, modelcheck::Mode mode, bool whole) {
  if (value.infinite) return " = infinity";
  if (mode == modelcheck::Mode::kExact) {
    const std::string exact = to_string(value.exact);
    if (!whole && exact.size() > kMaxPrintedFraction) return " = " + describe(value.exact);
    if (value.exact.get_den() == 1) return " = " + exact;
    std::ostringstream approx;
    approx.precision(10);
    approx << value.exact.get_d();
    return " = " + exact + " (about " + approx.str() + ")";
  }
  return " in [" + shortest_double(value.lower) + ", " + shortest_double(value.upper) + "]";
}

std::string truth_text(const property::Answer& answer, const model::ExplicitModel& model) {
  std::string text = answer.verdict ? " is true" : " is false";
  if (answer.considered == 1) return text + " in the initial state";
  if (answer.verdict && answer.holding == answer.considered)
    return text + " in all " + std::to_string(answer.considered) + " states read";
  text += ": it holds in " + std::to_string(answer.holding) + " of " +
          std::to_string(answer.considered) + " states read";
  if (answer.first_failing)
    text += " (first that fails: " + model.states.name(*answer.first_failing) + ")";
  return text;
}

// One property's scheduler as JSON: per state, its name and the action it takes (null where
// any action will do); a step-bounded property's per step.
nlohmann::json scheduler_json(const property::Property& property,
                              const modelcheck::Scheduler& scheduler,
                              const model::ExplicitModel& model) {
  const auto actions = [&](const std::vector<model::ActionIndex>& by_state) {
    nlohmann::json list = nlohmann::json::array();
    for (model::StateIndex s = 0; s < by_state.size(); ++s) {
      const model::ActionIndex a = by_state[s];
      list.push_back({{"state", model.states.name(s)},
                      {"action", a < model.num_actions() ? nlohmann::json(model.actions[a])
                                                         : nlohmann::json(nullptr)}});
    }
    return list;
  };
  nlohmann::json entry = {{"property", property.text}};
  if (property.name) entry["name"] = *property.name;
  if (!scheduler.action.empty()) {
    entry["memoryless"] = actions(scheduler.action);
  } else {
    nlohmann::json steps = nlohmann::json::array();
    for (const auto& step : scheduler.by_step)
      steps.push_back(actions(step));
    entry["by_step"] = std::move(steps);
  }
  return entry;
}

// PRISM's -exportadv form: the Markov chain a memoryless scheduler induces, as a .tra file
// ("STATES TRANSITIONS", then "SOURCE TARGET PROBABILITY ACTION" rows), probabilities exact.
std::string adversary_text(const model::ExplicitModel& model,
                           const std::vector<model::ActionIndex>& actions) {
  const model::TransitionMatrix& matrix = *model.contexts.front().transitions;
  std::string rows;
  std::size_t count = 0;
  for (model::StateIndex s = 0; s < matrix.num_states; ++s) {
    const model::ActionIndex a = property::scheduled_action(matrix, actions, s);
    if (a >= matrix.num_actions) continue;
    for (model::EdgeIndex e = matrix.edges_begin(s, a); e < matrix.edges_end(s, a); ++e, ++count) {
      rows += std::to_string(s) + " " + std::to_string(matrix.edge_target[e]) + " " +
              to_string(model.values[matrix.edge_probability[e]]) + " " + model.actions[a] + "\n";
    }
  }
  return std::to_string(matrix.num_states) + " " + std::to_string(count) + "\n" + rows;
}

bool write_text(const std::string& path, const std::string& text) {
  std::string error;
  if (write_atomically(path, text, error)) return true;
  report_error(kProgram, error);
  return false;
}

bool write_schedulers(const std::string& path, const nlohmann::json& schedulers) {
  return write_text(path, nlohmann::json{{"schedulers", schedulers}}.dump(1) + "\n");
}

void print_answer(const property::Property& property, const property::Answer& answer,
                  const model::ExplicitModel& model, bool whole_fractions) {
  std::cout << (property.name ? "\"" + *property.name + "\": " : "") << property.text;
  if (answer.kind == property::Answer::Kind::kNumber) {
    std::cout << value_text(answer.value, answer.mode, whole_fractions);
  } else {
    std::cout << truth_text(answer, model);
  }
  std::cout << "  [" << answer.method << "]\n";
}

int run_query(const QueryOptions& options) {
  SourceManager sources;
  DiagnosticEngine diagnostics(sources, std::cerr, options.common.max_errors);
  const std::vector<property::PropertiesFile> files =
      read_properties(options, sources, diagnostics);
  if (diagnostics.has_errors()) return 1;
  LoadOptions load = effective_load_options(options.common);
  if (load.rewards == "none") load.rewards = rewards_used(files);
  load.hash_source = false;
  const auto loaded = load_model(options.model, sources, diagnostics, load);
  if (!loaded || !loaded->model || diagnostics.has_errors()) {
    if (loaded && !loaded->model)
      diagnostics.file_error(options.model, "properties are answered on discrete models only");
    return 1;
  }
  const model::ExplicitModel& model = *loaded->model;
  for (const model::Context& context : model.contexts) {
    if (context.transitions != model.contexts.front().transitions) {
      diagnostics.file_error(options.model,
                             "context '" + context.name +
                                 "' has transitions of its own: "
                                 "properties are answered on models whose contexts share theirs (a "
                                 "PRISM program, an imported model, a spec without per-context "
                                 "dynamics)");
      return 1;
    }
  }
  modelcheck::Options engine;
  engine.precision = options.precision;
  engine.max_number_bits = load.max_number_bits;
  const bool exact = options.mode == "exact" ||
                     (options.mode == "auto" && model.num_states() <= modelcheck::kAutoExactStates);
  engine.mode = exact ? modelcheck::Mode::kExact : modelcheck::Mode::kSound;
  if (options.mode == "auto")
    engine.max_number_bits = std::min(engine.max_number_bits, modelcheck::kAutoExactNumberBits);
  engine.want_scheduler = !options.scheduler_path.empty();
  bool all_answered = true;
  nlohmann::json schedulers = nlohmann::json::array();
  std::vector<std::vector<model::ActionIndex>> memoryless;  // for an .adv file
  for (const property::PropertiesFile& file : files) {
    property::Evaluator evaluator(model, loaded->names, file, diagnostics, engine);
    evaluator.allow_sound_fallback(options.mode == "auto");
    evaluator.use_bisimulation(options.bisimulation);
    for (const property::Property& property : file.properties) {
      const std::optional<property::Answer> answer = evaluator.answer(property);
      if (!answer) {
        all_answered = false;
        if (diagnostics.should_stop()) return 1;
        continue;
      }
      print_answer(property, *answer, model, options.whole_fractions);
      if (!answer->scheduler) continue;
      schedulers.push_back(scheduler_json(property, *answer->scheduler, model));
      memoryless.push_back(answer->scheduler->action);
    }
  }
  if (options.scheduler_path.ends_with(".adv")) {
    // PRISM's adversary file holds one memoryless scheduler.
    if (memoryless.size() != 1 || memoryless.front().empty()) {
      report_error(kProgram, "an .adv file holds one memoryless scheduler, and " +
                                 std::to_string(memoryless.size()) +
                                 " properties gave one: ask for one unbounded Pmin/Pmax/Rmin/Rmax "
                                 "property, or write JSON");
      return 1;
    }
    if (!write_text(options.scheduler_path, adversary_text(model, memoryless.front()))) return 1;
  } else if (!options.scheduler_path.empty() &&
             !write_schedulers(options.scheduler_path, schedulers)) {
    return 1;
  }
  return all_answered ? 0 : 1;
}

}  // namespace

CommandRunner add_query_command(CLI::App& app) {
  auto options = std::make_shared<QueryOptions>();
  CLI::App* command = app.add_subcommand(
      "query", "Answer PRISM properties (P=?, Pmax=?, R{\"r\"}=?, P>=b ...) on a model");
  command->footer(
      "Each property is answered on one line, in the model's initial state (PRISM's\n"
      "filter(first, ..., \"init\")), with the method that gave the answer. Modes:\n"
      "  exact  rationals: graph precomputation, then an exact solve (1/6, not 0.1666...)\n"
      "  sound  an interval [lower, upper] that contains the true value, of width at most\n"
      "         --precision, by interval iteration with outward rounding; never a value\n"
      "         iteration stopped at a threshold\n"
      "  auto   exact up to 100000 states, sound past it, or when the exact solve refuses\n"
      "         or its numbers pass 2^16 bits\n"
      "The language is PRISM's (docs/properties.md): P=? [F \"goal\"], Pmax=? [a U<=10 b],\n"
      "P>=0.5 [G !\"crash\"], R{\"time\"}min=? [F \"done\"], R=? [C<=5], R=? [I=3],\n"
      "filter(max, P=? [F \"one\"], \"init\"); labels in quotes, the program's variables,\n"
      "constants and formulas by name.\n\n"
      "Examples:\n"
      "  oasisc query die.pm --prop 'P=? [F s=7&d=1]'\n"
      "  oasisc query leader.nm --const N=4 --props leader.props --mode sound");
  command
      ->add_option(
          "model", options->model,
          "PRISM program (.pm, .nm, .prism), discrete spec (.oasis) or model (.tra, .drn, .aut)")
      ->required();
  command->add_option("--prop", options->props, "A property, or several separated by ';'");
  command->add_option("--props", options->prop_files, "A file of properties (.props, .pctl)");
  command->add_option("--mode", options->mode, "exact, sound or auto")
      ->capture_default_str()
      ->check(CLI::IsMember({"exact", "sound", "auto"}));
  command
      ->add_option("--precision", options->precision,
                   "Sound mode: the widest interval an answer may have")
      ->capture_default_str()
      ->check(real_in(closed(1e-15, 0.5)));
  command->add_flag("--bisimulation", options->bisimulation,
                    "Answer each operator on the coarsest bisimulation quotient that respects its "
                    "state sets and rewards, and lift the values back (as Storm's --bisimulation)");
  command->add_flag("--whole-fractions", options->whole_fractions,
                    "Print exact answers whole, however long (by default a fraction of more "
                    "than 2000 characters is shown in scientific form with its length)");
  command->add_option("--scheduler", options->scheduler_path,
                      "Write the optimal scheduler of each Pmin/Pmax/Rmin/Rmax property to this "
                      "JSON file (per state, the action taken; re-checked on the model first); "
                      "a name ending in .adv gets PRISM's adversary form instead (the chain the "
                      "one scheduler induces, as a .tra file)");
  add_common_options(*command, options->common);
  command->callback([options] {
    if (options->props.empty() && options->prop_files.empty())
      throw CLI::ValidationError("query", "give at least one --prop or --props");
  });
  return [options] { return run_query(*options); };
}

}  // namespace oasis::cli
