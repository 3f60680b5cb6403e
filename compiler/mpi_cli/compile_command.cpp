// `oasisc-mpi compile SPEC -o DIR`: `oasisc compile` of a discrete model with its contexts
// dealt out to the ranks (distributed/context_spreading.hpp). Every rank loads the model;
// rank 0 reports its problems, gathers the abstractions and writes the catalog, the same
// files `oasisc compile` writes.

#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>

#include "codegen/catalog_files.hpp"
#include "command_line/memory_option.hpp"
#include "command_line/number_options.hpp"
#include "command_line/output_names.hpp"
#include "distributed/context_spreading.hpp"
#include "input/model_loader.hpp"
#include "mpi_cli/commands.hpp"
#include "support/error_report.hpp"
#include "support/limits.hpp"
#include "support/staged_directory.hpp"

namespace oasis::mpi_cli {
namespace {

namespace fs = std::filesystem;

struct CompileOptions : codegen::CatalogFileOptions {
  std::string output;  // default: the spec's file name without its extension
  std::optional<double> p_correct;
  unsigned jobs = 0;
  input::LoadOptions load;
};

// Every rank loads the same model; only rank 0's diagnostics are shown (the others are the
// same). nullopt on every rank when it cannot be compiled here.
std::optional<model::ExplicitModel> load_discrete_model(
    const CompileOptions& options, const distributed::Communicator& communicator,
    std::uint64_t& hash) {
  SourceManager sources;
  std::ostringstream others;
  DiagnosticEngine diagnostics(sources, communicator.is_root() ? std::cerr : others);
  input::LoadOptions load = options.load;
  load.memory_budget = cli::command_memory_budget();  // each rank loads the whole model
  auto loaded = input::load_model(options.spec, sources, diagnostics, load);
  if (communicator.any(!loaded || diagnostics.has_errors())) return std::nullopt;
  hash = loaded->source_hash;
  std::string problem;
  if (!loaded->model) {
    problem = "a continuous spec's contexts share its geometry: compile it with 'oasisc compile'";
  } else if (loaded->model->num_states() == 0 || loaded->model->contexts.empty()) {
    problem = "the model has no states or no contexts";
  } else if (!loaded->properties.empty()) {
    problem =
        "the spec states properties, which oasisc-mpi does not answer yet: compile it "
        "with 'oasisc compile'";
  } else if (codegen::wants(options, "svg")) {
    problem = "--format svg draws continuous abstractions; use dot for a discrete model";
  }
  if (!problem.empty()) {
    if (communicator.is_root()) report_error(options.spec, problem);
    return std::nullopt;
  }
  return std::move(loaded->model);
}

// On rank 0: the catalog of `abstractions`, written as one unit into the output folder.
bool write_catalog(const CompileOptions& options, const model::ExplicitModel& model,
                   const std::vector<pipeline::DiscreteAbstraction>& abstractions,
                   std::uint64_t hash) {
  std::string error;
  auto catalog = pipeline::catalog_data(model, abstractions, hash, {options.p_correct}, error);
  if (!catalog) {
    report_error(options.spec, error);
    return false;
  }
  StagedDirectory directory;
  if (!directory.open(options.output, error)) {
    report_error(options.output, error);
    return false;
  }
  codegen::OutputSet out(directory.staging_path());
  if (!codegen::write_discrete_catalog(options, *catalog, out, error) ||
      !directory.commit(codegen::marker_text(options, hash, out), error)) {
    report_error(options.output, error);
    return false;
  }
  for (const std::string& name : out.names())
    std::cout << "wrote " << (fs::path(options.output) / name).string() << '\n';
  return true;
}

int run_compile(CompileOptions options, const distributed::Communicator& communicator) {
  if (options.formats.empty()) options.formats = {"bin", "json", "dot"};
  if (options.output.empty()) options.output = fs::path(options.spec).stem().string();
  std::uint64_t hash = 0;
  const std::optional<model::ExplicitModel> model =
      load_discrete_model(options, communicator, hash);
  if (!model) return 1;
  pipeline::DiscreteOptions abstraction;
  abstraction.solve = true;
  abstraction.jobs = options.jobs;
  std::string error;
  std::vector<pipeline::DiscreteAbstraction> abstractions;
  bool written =
      distributed::abstract_contexts_spread(*model, abstraction, communicator, abstractions, error);
  if (communicator.is_root()) {
    if (!written)
      report_error(options.spec, error);
    else
      written = write_catalog(options, *model, abstractions, hash);
  }
  return communicator.any(!written) ? 1 : 0;
}

}  // namespace

CommandRunner add_compile_command(CLI::App& app, const distributed::Communicator& communicator) {
  auto options = std::make_shared<CompileOptions>();
  CLI::App* command = app.add_subcommand(
      "compile", "A catalog of a discrete model, its contexts dealt out to the ranks");
  command->footer(
      "What 'oasisc compile' does for a discrete spec, a PRISM program or an imported model,\n"
      "with context c abstracted by rank c mod P: each rank loads the model, computes the\n"
      "coarsest bisimulation quotient and the policy of its contexts, and sends rank 0 the\n"
      "partitions and policies; rank 0 writes the catalog, the same files 'oasisc compile'\n"
      "writes, as one unit into DIR. Every rank holds the whole model: this spreads the work\n"
      "of many contexts over machines. For one model too large for one machine, see\n"
      "'oasisc-mpi quotient'.\n\n"
      "Ctrl-C or SIGTERM to mpirun: DIR stays the whole old catalog or becomes the whole new\n"
      "one. The ranks remove their unfinished output in the second mpirun gives them before\n"
      "its SIGKILL (more with --mca odls_base_sigkill_timeout N); what a SIGKILL leaves, the\n"
      "next compile to DIR removes.\n\n"
      "Examples:\n"
      "  mpirun -np 2 oasisc-mpi compile specs/discrete_tracking.oasis -o out\n"
      "  oasisc verify specs/discrete_tracking.oasis out/discrete_tracking.bin\n"
      "  mpirun -np 4 oasisc-mpi compile model.nm --rewards all -o out --format bin,cpp");
  command->add_option("spec", options->spec, "Spec (.oasis), PRISM program or model file")
      ->required();
  command->add_option("-o,--output", options->output,
                      "Output directory (default: the spec's file name without extension)");
  command
      ->add_option("-f,--format", options->formats,
                   "Formats: bin, json, dot, cpp (default: bin,json,dot)")
      ->delimiter(',')
      ->check(CLI::IsMember({"bin", "json", "dot", "cpp"}));
  command
      ->add_option("--basename", options->basename,
                   "File name (without extension) of the C++ output, inside the output folder")
      ->check(cli::plain_file_name());  // never a path: compile writes nowhere else
  command
      ->add_option("--robust", options->p_correct,
                   "Add the robust filter's section with this sensor accuracy P = 1 - noise")
      ->check(cli::real_in(cli::closed(0.0, 1.0)));
  command
      ->add_option("-j,--jobs", options->jobs,
                   "Threads per rank for its contexts (0: one per hardware thread)")
      ->capture_default_str()
      ->check(cli::whole_in(0, limits::kMaxJobs));
  command
      ->add_option("--max-states", options->load.max_states,
                   "Stop exploring a factored model past this many states (by default only "
                   "what 32-bit state numbers cannot hold: --memory-budget bounds the model)")
      ->capture_default_str()
      ->check(cli::whole_in(1, limits::kMaxStates));
  command->add_option("--const", options->load.constants,
                      "PRISM programs: values of undefined constants (N=4,p=0.1)");
  command
      ->add_option("--rewards", options->load.rewards,
                   "PRISM programs: the reward structures that become contexts: none, all, "
                   "or names separated by commas")
      ->capture_default_str();
  return [options, &communicator] { return run_compile(*options, communicator); };
}

}  // namespace oasis::mpi_cli
