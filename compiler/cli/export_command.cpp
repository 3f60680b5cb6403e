// `oasisc export FILE --format aut|prism -o OUT`: one context of a model as a file other
// tools read (mCRL2's .aut, PRISM's explicit files), to cross-check our results with theirs.

#include <iostream>
#include <memory>

#include "cli/commands.hpp"
#include "formats/aut_writer.hpp"
#include "formats/explicit_writer.hpp"
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
  const auto context = choose_context(*loaded->model, options.context, options.file);
  if (!context) return 1;
  std::string error;
  const bool written =
      options.format == "aut"
          ? formats::write_aut_file(*loaded->model, *context, options.output, error)
          : formats::write_prism(*loaded->model, *context, options.output, error);
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
      "Probabilities are written exactly. Output appears whole or not at all. See\n"
      "docs/formats.md.\n\n"
      "Examples:\n"
      "  oasisc export specs/discrete_tracking.oasis --context object_at_s1 --format aut -o t.aut\n"
      "  oasisc export model.aut --format prism -o model   # writes model.tra, model.lab, ...");
  command
      ->add_option("file", options->file,
                   "Spec (.oasis), PRISM program (.pm, .nm, .prism) or model (.aut, .tra) file")
      ->required();
  command->add_option("-c,--context", options->context,
                      "Context to export (needed when the model has several)");
  command->add_option("-f,--format", options->format, "Output format")
      ->required()
      ->check(CLI::IsMember({"aut", "prism"}));
  command
      ->add_option("-o,--output", options->output,
                   "Output file (aut; '-' for standard output) or base name (prism; '.tra' "
                   "may be given)")
      ->required();
  add_common_options(*command, options->common);
  return [options] { return run_export(*options); };
}

}  // namespace oasis::cli
