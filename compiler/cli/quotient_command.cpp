// `oasisc quotient FILE`: the coarsest bisimulation quotient of every context.

#include <chrono>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <mutex>

#include <nlohmann/json.hpp>
#include <unistd.h>

#include "bisim/quotient.hpp"
#include "cli/commands.hpp"
#include "cli/label_options.hpp"
#include "cli/quotient_output.hpp"
#include "command_line/number_options.hpp"
#include "files/output_names.hpp"
#include "formats/aut_writer.hpp"
#include "pipeline/discrete_catalog.hpp"
#include "support/atomic_file.hpp"
#include "support/atomic_file_set.hpp"
#include "support/error_report.hpp"
#include "support/limits.hpp"
#include "support/peak_memory.hpp"
#include "text/printable_text.hpp"

namespace oasis::cli {
namespace {

struct QuotientOptions {
  std::string file;
  std::vector<std::string> contexts;
  std::string format = "text";
  std::string output;
  bool partition = false;
  std::optional<double> rounding_step;  // --epsilon: the approximate mode's rounding step
  std::string respect_labels = "all";
  std::string choices = "labelled";  // --choices: labelled (Definition 1) or unlabelled (Storm)
  unsigned jobs = 0;
  CommonOptions common;
};

// "the model has no context 'NAME' (it has: A B)".
std::string no_such_context(const model::ExplicitModel& model, const std::string& name) {
  std::string names;
  for (const auto& context : model.contexts)
    names += ' ' + context.name;
  return "the model has no context '" + name + "' (it has:" + names + ")";
}

// The contexts to quotient: those named, or all.
std::optional<std::vector<std::size_t>> select_contexts(const model::ExplicitModel& model,
                                                        const QuotientOptions& options) {
  std::vector<std::size_t> selected;
  if (options.contexts.empty()) {
    for (std::size_t c = 0; c < model.contexts.size(); ++c)
      selected.push_back(c);
    return selected;
  }
  for (const std::string& name : options.contexts) {
    std::size_t c = 0;
    while (c < model.contexts.size() && model.contexts[c].name != name)
      ++c;
    if (c == model.contexts.size()) {
      report_error(options.file, no_such_context(model, name));
      return std::nullopt;
    }
    selected.push_back(c);
  }
  return selected;
}

// With one file per context (aut, dot), a context's name becomes part of a file name: a name
// that is a path (a PRISM reward structure "a/../../x") would write elsewhere, and no two
// contexts may share a file (the one rule for output names, common/files/output_names.hpp).
// Checked before any work; false after saying why.
bool context_files_allowed(const model::ExplicitModel& model,
                           const std::vector<std::size_t>& selected,
                           const QuotientOptions& options) {
  const bool per_context = (options.format == "aut" || options.format == "dot") &&
                           selected.size() > 1 && !options.output.empty() && options.output != "-";
  if (!per_context) return true;
  std::vector<std::string> paths;
  for (const std::size_t c : selected) {
    paths.push_back(output_path(options.output, options.format, model.contexts[c].name, true));
    const std::string problem = files::plain_file_name_problem(
        std::filesystem::path(options.output).stem().string() + "." + model.contexts[c].name);
    if (!problem.empty()) {
      report_error(options.file, "context \"" + text::printable_excerpt(model.contexts[c].name) +
                                     "\" cannot name a file: " + problem +
                                     "; choose other contexts with -c");
      return false;
    }
  }
  if (const auto shared = files::first_shared_output(paths)) {
    report_error(
        options.file,
        "contexts \"" + text::printable_excerpt(model.contexts[selected[shared->first]].name) +
            "\" and \"" + text::printable_excerpt(model.contexts[selected[shared->second]].name) +
            "\" would both be written to " + paths[shared->first]);
    return false;
  }
  return true;
}

// Refines the selected contexts in parallel, through the compiler's pipeline (partitions only).
std::vector<pipeline::DiscreteAbstraction> run_contexts(const model::ExplicitModel& model,
                                                        const std::vector<std::size_t>& selected,
                                                        const QuotientOptions& options,
                                                        std::vector<std::uint32_t> label_class,
                                                        bool progress) {
  pipeline::DiscreteOptions refinement;
  refinement.rounding_step = options.rounding_step;
  refinement.label_class = std::move(label_class);
  refinement.unlabelled_choices = options.choices == "unlabelled";
  refinement.solve = false;
  refinement.jobs = options.jobs;
  std::mutex output;
  if (progress) {
    refinement.progress = [&](std::size_t c, const bisim::RefinementProgress& p) {
      const std::lock_guard lock(output);
      std::cerr << "\rrefining " << model.contexts[c].name << ": " << p.blocks << " blocks, "
                << p.splitters_processed << " splitters done, " << p.splitters_queued
                << " queued\033[K" << std::flush;
    };
  }
  std::string error;  // only a policy can fail, and none is solved here
  auto results = pipeline::abstract_contexts(model, selected, refinement, error);
  if (progress) std::cerr << "\r\033[K" << std::flush;
  return std::move(*results);
}

int write_output(const LoadedModel& loaded,
                 const std::vector<pipeline::DiscreteAbstraction>& results,
                 const QuotientOptions& options, double load_seconds) {
  const model::ExplicitModel& model = *loaded.model;
  const bool to_stdout = options.output.empty() || options.output == "-";
  std::ostream& summary = (options.format == "text" || !to_stdout) ? std::cout : std::cerr;
  print_summary(summary, model, results, load_seconds, peak_memory_mib(), options.rounding_step);
  if (!model.labels.empty())
    summary << "labels: " << model.labels.names.size() << "; respected: " << options.respect_labels
            << '\n';
  if (options.format == "text") return 0;

  std::string error;
  AtomicFileSet files;  // every context's file is replaced, or none
  for (std::size_t i = 0; i < results.size(); ++i) {
    if (options.format == "json" && i > 0) break;  // one JSON document holds every context
    const std::string path =
        output_path(options.output, options.format, model.contexts[results[i].context].name,
                    options.format != "json" && results.size() > 1);
    // Text for the terminal goes through std::cout; an .aut, even to '-', through AtomicFile.
    const bool through_cout = to_stdout && options.format != "aut";
    AtomicFile* file = through_cout ? nullptr : files.add(path, error);
    if (!through_cout && file == nullptr) {
      report_error(path, error);
      return 1;
    }
    std::string text;
    if (options.format == "json") {
      nlohmann::json json = quotient_json(loaded, results, load_seconds, peak_memory_mib(),
                                          options.partition, options.rounding_step);
      // What `verify` must respect to check these partitions.
      json["respected_labels"] = options.respect_labels;
      json["choices"] = options.choices;
      text = json.dump(2) + "\n";
    } else {
      const model::ExplicitModel quotient =
          bisim::build_quotient(model, results[i].context, results[i].partition);
      if (options.format == "aut") {
        if (!formats::write_aut(quotient, 0, *file, error)) {
          report_error(path, error);
          return 1;
        }
        continue;
      }
      text = quotient_dot(model, results[i], quotient);
    }
    if (through_cout) {
      std::cout << text;
    } else {
      file->append(text);
    }
  }
  if (!files.commit(error)) {
    report_error(options.output, error);
    return 1;
  }
  return 0;
}

int run_quotient(const QuotientOptions& options) {
  // A quotient .aut can be as large as the model, so standard output must be asked for.
  if (options.choices == "unlabelled" && (options.format == "aut" || options.format == "dot")) {
    report_error(kProgram,
                 "--choices unlabelled gives partitions (text, json): the quotient MDP that aut "
                 "and dot write names its choices by action");
    return 2;
  }
  if (options.choices == "unlabelled" && options.rounding_step) {
    report_error(kProgram,
                 "--choices unlabelled compares probabilities exactly; it does not take --epsilon");
    return 2;
  }
  if (options.format == "aut" && options.output.empty()) {
    report_error(kProgram,
                 "--format aut writes files: give one with -o FILE (or -o - for standard output)");
    return 2;
  }
  SourceManager sources;
  DiagnosticEngine diagnostics(sources, std::cerr, options.common.max_errors);
  const auto start = std::chrono::steady_clock::now();
  LoadOptions load_options = effective_load_options(options.common);
  load_options.hash_source = false;  // a quotient is not a catalog: no spec hash to record
  auto loaded = load_model(options.file, sources, diagnostics, load_options);
  if (!loaded || diagnostics.has_errors()) return 1;
  if (!loaded->model) {
    report_error(options.file,
                 "quotient takes explicit models; a continuous spec is partitioned and quotiented "
                 "by 'oasisc compile " +
                     options.file +
                     " -o DIR --format json' (its JSON has every context's cells and blocks)");
    return 1;
  }
  const double load_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const auto selected = select_contexts(*loaded->model, options);
  if (!selected) return 1;
  if (options.format == "aut" && options.output == "-" && selected->size() > 1) {
    report_error(kProgram, "--format aut writes one file per context and the model has " +
                               std::to_string(selected->size()) +
                               ": choose one with --context to write it to standard output, or "
                               "give -o FILE");
    return 2;
  }
  if (!context_files_allowed(*loaded->model, *selected, options)) return 1;
  auto label_class = respected_label_classes(*loaded->model, options.respect_labels, options.file);
  if (!label_class) return 1;
  const auto results = run_contexts(*loaded->model, *selected, options, std::move(*label_class),
                                    load_options.progress);
  return write_output(*loaded, results, options, load_seconds);
}

}  // namespace

CommandRunner add_quotient_command(CLI::App& app) {
  auto options = std::make_shared<QuotientOptions>();
  CLI::App* command =
      app.add_subcommand("quotient", "Compute the coarsest bisimulation quotient of every context");
  command->footer(
      "Two states are bisimilar when, for every action, both have it enabled or neither,\n"
      "their rewards R(s,a) are equal, and their probabilities of reaching every block are\n"
      "equal (the paper's Definition 1); and they hold the same respected labels (a PRISM\n"
      ".lab file's; --respect-labels, all by default, as Storm). Probabilities are compared "
      "exactly; --epsilon\n"
      "rounds them instead, for models written with floating-point numbers, and says so in\n"
      "its output (docs/bisimulation.md explains what that mode guarantees).\n\n"
      "Formats: text (a summary), json (keys contexts[].name, states, transitions, blocks,\n"
      "seconds; with --partition also contexts[].partition), aut (the quotient MDP for\n"
      "mCRL2 and 'oasisc info'), dot (Graphviz). With several contexts, aut and dot write\n"
      "one file per context: OUT with the context name before the extension.\n\n"
      "Examples:\n"
      "  oasisc quotient specs/discrete_tracking.oasis\n"
      "  oasisc quotient specs/discrete_tracking.oasis --format json --partition -o result.json\n"
      "  oasisc verify specs/discrete_tracking.oasis result.json\n"
      "  oasisc quotient model.aut --format aut -o model.min.aut");
  command
      ->add_option("file", options->file,
                   "Spec (.oasis), PRISM program (.pm, .nm, .prism) or model (.aut, .tra) file")
      ->required();
  command->add_option("-c,--context", options->contexts, "Quotient only this context (repeatable)");
  command->add_option("-f,--format", options->format, "Output: text, json, aut or dot")
      ->capture_default_str()
      ->check(CLI::IsMember({"text", "json", "aut", "dot"}));
  command->add_option("-o,--output", options->output,
                      "Output file; '-' or none: standard output (aut: only with -o -)");
  command->add_flag("--partition", options->partition, "Include the blocks in the JSON output");
  command
      ->add_option("--epsilon", options->rounding_step,
                   "Compare probabilities rounded to multiples of E (approximate mode)")
      ->check(real_in(closed(1e-15, 0.5)));
  add_respect_labels_option(*command, options->respect_labels);
  command
      ->add_option("--choices", options->choices,
                   "How the choices of two states are matched: labelled (by action name, "
                   "Definition 1: what a policy needs) or unlabelled (as sets of distributions, "
                   "whatever their names: Storm's MDP bisimulation)")
      ->capture_default_str()
      ->check(CLI::IsMember({"labelled", "unlabelled"}));
  command
      ->add_option("-j,--jobs", options->jobs, "Contexts quotiented in parallel (default: cores)")
      ->check(whole_in(0, limits::kMaxJobs));
  add_common_options(*command, options->common);
  return [options] { return run_quotient(*options); };
}

}  // namespace oasis::cli
