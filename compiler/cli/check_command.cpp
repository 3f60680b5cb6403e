// `oasisc check FILE...`: report every problem in the given specs and models.

#include <iostream>
#include <memory>

#include "cli/commands.hpp"

namespace oasis::cli {
namespace {

struct CheckOptions {
  std::vector<std::string> files;
  CommonOptions common;
  bool quiet = false;
};

std::string describe_loaded(const LoadedModel& loaded) {
  std::string text;
  if (loaded.ir) {
    const auto& ir = *loaded.ir;
    const char* kind = ir.kind == model::ModelKind::Explicit   ? "explicit"
                       : ir.kind == model::ModelKind::Factored ? "factored"
                                                               : "continuous";
    text = "model '" + ir.name + "' (" + kind + "), ";
    if (ir.kind == model::ModelKind::Continuous) {
      text += std::to_string(ir.continuous.size()) + " continuous variables, ";
    }
  } else if (loaded.model) {
    text = "model '" + loaded.model->name + "' (" + (loaded.prism_program ? "prism" : "imported") +
           "), ";
  }
  if (loaded.model) text += std::to_string(loaded.model->num_states()) + " states, ";
  const std::size_t contexts =
      loaded.ir ? loaded.ir->contexts.size() : loaded.model->contexts.size();
  return text + std::to_string(contexts) + (contexts == 1 ? " context" : " contexts");
}

int run_check(const CheckOptions& options) {
  bool all_ok = true;
  for (const std::string& path : options.files) {
    // One engine per file: the error limit applies per file, and a broken file does not
    // stop the others from being checked.
    SourceManager sources;
    DiagnosticEngine diagnostics(sources, std::cerr, options.common.max_errors);
    auto loaded = load_model(path, sources, diagnostics, effective_load_options(options.common));
    if (loaded && !diagnostics.has_errors()) {
      if (!options.quiet) std::cout << path << ": ok: " << describe_loaded(*loaded) << '\n';
      continue;
    }
    all_ok = false;
    const std::size_t errors = diagnostics.error_count();
    std::cerr << errors << (errors == 1 ? " error" : " errors") << " in " << path << '\n';
  }
  return all_ok ? 0 : 1;
}

}  // namespace

CommandRunner add_check_command(CLI::App& app) {
  auto options = std::make_shared<CheckOptions>();
  CLI::App* command = app.add_subcommand(
      "check", "Check specs and imported models; print each problem as file:line:col");
  command->footer(
      "Every file is read, parsed, checked and (for discrete models) explored, so that\n"
      "problems that show only in some state, such as a variable leaving its range, are\n"
      "found too. Exit status: 0 when every file is sound, 1 otherwise.\n\n"
      "Example:\n  oasisc check specs/*.oasis");
  command
      ->add_option("files", options->files,
                   "Spec (.oasis), PRISM program (.pm, .nm, .prism) or model (.aut, .tra) files")
      ->required();
  command->add_flag("-q,--quiet", options->quiet, "Print only problems");
  add_common_options(*command, options->common);
  return [options] { return run_check(*options); };
}

}  // namespace oasis::cli
