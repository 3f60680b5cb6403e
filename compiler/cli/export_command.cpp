// `oasisc export FILE --format aut|prism|drn|umb -o OUT`: a model as a file other tools read
// (mCRL2's .aut, PRISM's explicit files, Storm's DRN, PRISM and Storm's UMB), to cross-check
// our results with theirs. .aut and PRISM files carry one context; DRN and UMB carry every
// context that shares the transitions, one reward model each.

#include <iostream>
#include <memory>
#include <vector>

#include "cli/commands.hpp"
#include "formats/aut_writer.hpp"
#include "formats/drn_writer.hpp"
#include "formats/explicit_writer.hpp"
#include "formats/umb_writer.hpp"
#include "support/error_report.hpp"

namespace oasis::cli {
namespace {

struct ExportOptions {
  std::string file;
  std::string context;
  std::string format;
  std::string output;
  CommonOptions common;
};

// The index of the context to export: the named one, or the only one.
std::optional<std::size_t> choose_context(const model::ExplicitModel& model,
                                          const std::string& name, const std::string& path) {
  std::string names;
  for (std::size_t c = 0; c < model.contexts.size(); ++c) {
    if (model.contexts[c].name == name) return c;
    names += (c ? ", " : "") + model.contexts[c].name;
  }
  if (name.empty() && model.contexts.size() == 1) return 0;
  report_error(path, (name.empty() ? "the model has several contexts"
                                   : "the model has no context '" + name + "'") +
                         "; choose one with --context (" + names + ")");
  return std::nullopt;
}

// DRN and UMB: the named context, else every context (which must share their transitions).
bool write_reward_models(const model::ExplicitModel& model, const ExportOptions& options,
                         std::string& error) {
  std::vector<std::size_t> contexts;
  if (options.context.empty()) {
    for (std::size_t c = 0; c < model.contexts.size(); ++c)
      contexts.push_back(c);
  } else {
    const auto context = choose_context(model, options.context, options.file);
    if (!context) return false;
    contexts.push_back(*context);
  }
  return options.format == "umb" ? formats::write_umb_file(model, contexts, options.output, error)
                                 : formats::write_drn_file(model, contexts, options.output, error);
}

int run_export(const ExportOptions& options) {
  if (options.format == "prism" && options.output == "-") {
    report_error(kProgram,
                 "--format prism writes several files (.tra, .lab, .srew, ...): give their base "
                 "name with -o; '-o -' (standard output) is for --format aut");
    return 2;
  }
  SourceManager sources;
  DiagnosticEngine diagnostics(sources, std::cerr, options.common.max_errors);
  auto loaded =
      load_model(options.file, sources, diagnostics, effective_load_options(options.common));
  if (!loaded || diagnostics.has_errors()) return 1;
  if (!loaded->model) {
    report_error(options.file,
                 "a continuous model has no explicit states to export before the geometry layer "
                 "partitions it");
    return 1;
  }
  std::string error;
  bool written = false;
  if (options.format == "drn" || options.format == "umb") {
    written = write_reward_models(*loaded->model, options, error);
    if (!written && error.empty()) return 1;  // a context that does not exist, reported
  } else {
    const auto context = choose_context(*loaded->model, options.context, options.file);
    if (!context) return 1;
    written = options.format == "aut"
                  ? formats::write_aut_file(*loaded->model, *context, options.output, error)
                  : formats::write_prism(*loaded->model, *context, options.output, error);
  }
  if (!written) {
    report_error(options.output, error);
    return 1;
  }
  return 0;
}

}  // namespace

CommandRunner add_export_command(CLI::App& app) {
  auto options = std::make_shared<ExportOptions>();
  CLI::App* command = app.add_subcommand(
      "export", "Write one context of a model in a format other tools read (.aut, PRISM)");
  command->footer(
      "Formats:\n"
      "  aut    mCRL2's probabilistic Aldebaran format; rewards travel in the labels\n"
      "  prism  PRISM's explicit files: OUT.tra, OUT.lab, OUT.srew, and OUT.sta / OUT.trew\n"
      "         when the model has variables / state-action rewards\n"
      "  drn    Storm's DRN: labels, and every context as a reward model (or the one\n"
      "         chosen with --context)\n"
      "  umb    UMB, the binary format of PRISM 4.10 and Storm (a gzip-compressed tar):\n"
      "         what drn carries, every number an exact rational\n"
      "Probabilities are written exactly. Output appears whole or not at all. See\n"
      "docs/formats.md.\n\n"
      "Examples:\n"
      "  oasisc export specs/discrete_tracking.oasis --context object_at_s1 --format aut -o t.aut\n"
      "  oasisc export model.aut --format prism -o model   # writes model.tra, model.lab, ...\n"
      "  oasisc export tests/data/prism/two_dice.nm --format umb -o dice.umb");
  command
      ->add_option("file", options->file,
                   "Spec (.oasis), PRISM program (.pm, .nm, .prism) or model (.aut, .tra, .drn, "
                   ".umb) file")
      ->required();
  command->add_option("-c,--context", options->context,
                      "Context to export (needed for aut and prism when the model has several)");
  command->add_option("-f,--format", options->format, "Output format")
      ->required()
      ->check(CLI::IsMember({"aut", "prism", "drn", "umb"}));
  command
      ->add_option("-o,--output", options->output,
                   "Output file (aut, drn, umb; '-' for standard output) or base name (prism; "
                   "'.tra' may be given)")
      ->required();
  add_common_options(*command, options->common);
  return [options] { return run_export(*options); };
}

}  // namespace oasis::cli
