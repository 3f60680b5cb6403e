// oasis-sim: experiments of the paper on the compiled catalog and the runtime filter.
//   oasis-sim table1 [--spec FILE] [--seeds N] [--steps N] [--sigma S] [--noise R...]
//                    [--filters F...] [--json PATH] [--csv-dir DIR] [--plot DIR]

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <new>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>

#include "command_line/empty_values.hpp"
#include "command_line/memory_option.hpp"
#include "command_line/number_options.hpp"
#include "frontend/load_spec.hpp"
#include "model/catalog_data.hpp"
#include "model/explorer.hpp"
#include "oasis/rt/spec_hash.hpp"
#include "support/error_report.hpp"
#include "support/interrupt_cleanup.hpp"
#include "support/standard_output.hpp"
#include "table1/report.hpp"
#include "table1/table1.hpp"

namespace {

using namespace oasis;

// The name oasis-sim's messages begin with when they belong to no file.
constexpr std::string_view kProgram = "oasis-sim";

// The paper's discrete example: in the source tree the program was built from, or where
// `cmake --install` put it (PREFIX/share/oasis/specs, next to PREFIX/bin/oasis-sim).
std::string default_spec() {
  namespace fs = std::filesystem;
  std::error_code error;
  if (fs::exists(OASIS_SIM_DEFAULT_SPEC, error)) return OASIS_SIM_DEFAULT_SPEC;
  const fs::path program = fs::read_symlink("/proc/self/exe", error);
  const fs::path installed =
      program.parent_path().parent_path() / "share/oasis/specs/discrete_tracking.oasis";
  return !error && fs::exists(installed, error) ? installed.string() : OASIS_SIM_DEFAULT_SPEC;
}

struct Table1Arguments {
  std::string spec = default_spec();
  std::uint32_t seeds = 5;
  std::uint32_t steps = 500;
  double sigma = 0.7;
  std::vector<std::string> noises{"perceived", "process", "observed"};
  std::vector<std::string> filters{"paper", "keep", "guard", "soft", "robust", "hedged"};
  std::vector<std::string> declared{"observed"};
  std::uint32_t fit_runs = 0;
  std::string json;
  std::string csv_dir;
  std::string plot_dir;
};

int run_table1_command(const Table1Arguments& arguments) {
  table1::Table1Options options;
  options.seeds = arguments.seeds;
  options.steps = arguments.steps;
  options.sigma = arguments.sigma;
  options.noises.clear();
  for (const std::string& name : arguments.noises) {
    const auto noise = table1::parse_noise(name);
    if (!noise || *noise == table1::NoiseReading::kNone) {
      report_error(kProgram, "unknown noise reading '" + name + "' (perceived, process, observed)");
      return 2;
    }
    options.noises.push_back(*noise);
  }
  options.filters.clear();
  for (const std::string& name : arguments.filters) {
    const auto filter = table1::parse_filter(name);
    if (!filter) {
      report_error(kProgram,
                   "unknown filter '" + name + "' (paper, keep, guard, soft, robust, hedged)");
      return 2;
    }
    options.filters.push_back(*filter);
  }
  options.fit_runs = arguments.fit_runs;
  options.declared.clear();
  for (const std::string& name : arguments.declared) {
    const auto declared = table1::parse_noise(name);
    if (!declared || *declared == table1::NoiseReading::kNone) {
      report_error(kProgram,
                   "unknown declared reading '" + name + "' (perceived, process, observed)");
      return 2;
    }
    options.declared.push_back(*declared);
  }

  // The spec is read once, by the front end's reader (MappedFile: a FIFO nobody writes to is
  // refused after its grace period, and `--spec <(cat spec.oasis)` works), and the catalog's
  // hash is taken from the very bytes it parsed.
  SourceManager sources;
  DiagnosticEngine diagnostics(sources, std::cerr);
  const FileId spec_file = sources.num_files();
  const auto ir = frontend::load_spec(arguments.spec, sources, diagnostics);
  if (!ir) return 1;
  const std::string_view spec_text = sources.file(spec_file).text();
  auto model = model::explore(*ir, diagnostics);
  if (!model) return 1;
  std::vector<std::string> context_names;
  for (const auto& context : model->contexts)
    context_names.push_back(context.name);
  std::vector<std::string> state_names;
  for (std::uint32_t s = 0; s < model->num_states(); ++s)
    state_names.push_back(model->states.name(s));
  const table1::Table1Experiment experiment(std::move(*model), rt::spec_hash(spec_text));

  namespace fs = std::filesystem;
  std::string error;
  for (const std::string& dir : {arguments.csv_dir, arguments.plot_dir}) {
    std::error_code code;
    if (!dir.empty() && !fs::create_directories(dir, code) && code) {
      report_error(kProgram, "cannot create " + dir + ": " + code.message());
      return 1;
    }
  }
  bool sink_failed = false;
  const table1::TraceSink sink = [&](const table1::TrialSpec& spec, const table1::Trace& trace) {
    if (sink_failed) return;
    if (!arguments.csv_dir.empty() &&
        !table1::write_text(fs::path(arguments.csv_dir) / (table1::trial_stem(spec) + ".csv"),
                            table1::trace_csv(trace, context_names, state_names), error))
      sink_failed = true;
    const bool plotted = spec.pattern == table1::Pattern::kStep ||
                         spec.pattern == table1::Pattern::kPeriodic ||
                         spec.pattern == table1::Pattern::kUniformRandom;
    if (!arguments.plot_dir.empty() && plotted && spec.model.id == "i" &&
        !table1::write_text(fs::path(arguments.plot_dir) / (table1::trial_stem(spec) + ".svg"),
                            table1::trace_svg(spec, trace, context_names), error))
      sink_failed = true;
  };
  const auto rows = table1::run_table1(experiment, options, error, sink);
  if (!rows || sink_failed) {
    report_error(kProgram, error);
    return 1;
  }
  table1::print_table(std::cout, *rows, options);
  if (!arguments.json.empty() &&
      !table1::write_text(arguments.json, table1::rows_json(*rows).dump(2) + "\n", error)) {
    report_error(kProgram, error);
    return 1;
  }
  return 0;
}

}  // namespace

namespace {

// The program: its command line parsed, then the command run, every error of a command
// reported. main() catches what escapes the set-up.
int run(int argc, char** argv) {
  oasis::interrupt::install_cleanup_handlers();  // an interrupted run leaves no temporary file
  CLI::App app{"oasis-sim: the paper's experiments on the compiled catalog and the runtime filter"};
  app.require_subcommand(1);
  Table1Arguments table1;
  CLI::App* command = app.add_subcommand(
      "table1", "Table I: the discrete-space tracking example (accuracy, average and max lag)");
  command->add_option("--spec", table1.spec, "the spec to load")->capture_default_str();
  command->add_option("--seeds", table1.seeds, "seeds per row (0 .. N-1)")
      ->capture_default_str()
      ->check(oasis::cli::whole_in(1, 100000));
  command->add_option("--steps", table1.steps, "steps per trial")
      ->capture_default_str()
      ->check(oasis::cli::whole_in(1, 10'000'000));
  command->add_option("--sigma", table1.sigma, "state-noise probability of the noisy patterns")
      ->capture_default_str()
      ->check(oasis::cli::real_in(oasis::cli::closed(0.0, 1.0)));
  command
      ->add_option("--noise", table1.noises,
                   "noise readings for the noisy patterns: perceived, process, observed")
      ->capture_default_str();
  command
      ->add_option("--filters", table1.filters, "filters: paper, keep, guard, soft, robust, hedged")
      ->capture_default_str();
  command
      ->add_option("--declared", table1.declared,
                   "the noise readings the robust and hedged filters assume, one column each: "
                   "observed (the reward follows the true state), perceived or process (it "
                   "follows the observed state)")
      ->capture_default_str();
  command
      ->add_option("--fit-switching", table1.fit_runs,
                   "add a transition model whose p(stay) is fitted per row, by maximum "
                   "likelihood, from this many training runs (on other seeds)")
      ->check(oasis::cli::whole_in(1, 1000));
  command->add_option("--json", table1.json, "write the rows as JSON to this file");
  command->add_option("--csv-dir", table1.csv_dir, "write per-trial CSV traces here");
  command->add_option("--plot", table1.plot_dir,
                      "write SVG plots (model (i), step/periodic/uniform_random, first 150 steps)");
  std::string memory_budget = "auto";
  oasis::cli::add_memory_budget_option(app, memory_budget);
  oasis::cli::refuse_empty_values(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int exit_status = app.exit(e);  // --help and --version: 0
    return oasis::finish_standard_output(kProgram, exit_status == 0 ? 0 : 2);  // bad usage
  }
  const std::optional<std::uint64_t> budget =
      oasis::cli::apply_memory_budget_option(app, memory_budget, kProgram);
  if (!budget) return oasis::finish_standard_output(kProgram, 2);
  int status = 1;
  try {
    status = run_table1_command(table1);
  } catch (const std::bad_alloc&) {
    oasis::cli::report_out_of_memory(kProgram, *budget);
  }
  return oasis::finish_standard_output(kProgram, status);
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (...) {
    // Only the set-up of the command line is left outside run()'s handlers: out of memory
    // before any command ran. No allocation here.
    std::fputs("oasis-sim: error: could not set up the command line\n", stderr);
    return 1;
  }
}
