// `oasisc-mpi quotient MODEL.aut -o OUT`: the coarsest bisimulation of an .aut model with
// the model spread over the ranks (docs/bisimulation.md, "Past one machine").

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "command_line/memory_option.hpp"
#include "command_line/number_options.hpp"
#include "distributed/distributed_reader.hpp"
#include "distributed/partition_output.hpp"
#include "distributed/quotient_output.hpp"
#include "distributed/signature_refinement.hpp"
#include "files/output_names.hpp"
#include "formats/aut_writer.hpp"
#include "mpi_cli/commands.hpp"
#include "support/error_report.hpp"
#include "support/limits.hpp"
#include "support/peak_memory.hpp"

namespace oasis::mpi_cli {
namespace {

using Clock = std::chrono::steady_clock;

struct Options {
  std::vector<std::string> models;
  std::string output;
  std::string format = "json";
  formats::ReadOptions read;
  bool rational_sums = false;
  bool progress = false;
  bool quiet = false;
};

constexpr const char* kFooter =
    "The coarsest probabilistic bisimulation of an MDP in mCRL2's .aut format, computed by\n"
    "every rank of an MPI job: the same partition as 'oasisc quotient', with the model spread\n"
    "over the ranks' memory.\n"
    "\n"
    "Each rank reads a part of the file and keeps the states s with s mod P equal to its rank\n"
    "(on several machines the file must be at the same path on each: a shared file system).\n"
    "Rounds of signature refinement follow (docs/bisimulation.md); rank 0 writes the\n"
    "partition as 'oasisc quotient --format json --partition' does, so that\n"
    "'oasisc verify MODEL PARTITION.json' checks it; or, with --format aut, the quotient MDP\n"
    "as 'oasisc quotient --format aut' writes it, byte for byte. Sums are exact: integers\n"
    "over a common denominator when it fits in 62 bits, GMP rationals otherwise.\n"
    "\n"
    "Examples:\n"
    "  mpirun -np 4 oasisc-mpi quotient model.aut -o partition.json\n"
    "  oasisc verify model.aut partition.json\n"
    "  mpirun -np 4 oasisc-mpi quotient model.aut --format aut -o quotient.aut\n"
    "  mpirun -np 2 oasisc-mpi quotient a.aut b.aut -o partitions/   (one JSON per model)\n"
    "  mpirun -np 16 --hostfile hosts oasisc-mpi quotient big.aut -o p.json --progress\n"
    "\n"
    "Other formats: 'oasisc export MODEL --format aut -o MODEL.aut' first.";

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// For the test of a rank lost mid-run: OASIS_MPI_KILL=RANK:ROUND makes that rank kill
// itself (SIGKILL, as the out-of-memory killer would) when that round starts.
void maybe_kill_self(std::uint32_t rank, std::uint32_t round) {
  const char* spec = std::getenv("OASIS_MPI_KILL");
  if (spec == nullptr) return;
  unsigned wanted_rank = 0;
  unsigned wanted_round = 0;
  char colon = 0;
  std::istringstream in(spec);
  if (in >> wanted_rank >> colon >> wanted_round && colon == ':' && wanted_rank == rank &&
      wanted_round == round) {
    std::raise(SIGKILL);
  }
}

std::string output_for(const Options& options, const std::string& model) {
  if (options.models.size() == 1) return options.output;
  return (std::filesystem::path(options.output) /
          (std::filesystem::path(model).stem().string() + "." + options.format))
      .string();
}

void print_summary(const distributed::RunFacts& facts, std::uint32_t states, std::uint64_t blocks,
                   const std::string& output) {
  const double peak = *std::max_element(facts.peak_memory_mib.begin(), facts.peak_memory_mib.end());
  std::cout << std::fixed << std::setprecision(3) << facts.model << ": " << states << " states, "
            << facts.transitions << " transitions, " << facts.ranks
            << (facts.ranks == 1 ? " rank" : " ranks") << "; read in " << facts.load_seconds
            << " s\n  " << blocks << (blocks == 1 ? " block" : " blocks") << " after "
            << facts.rounds << " rounds ("
            << (facts.exact_integer_sums ? "exact integer sums" : "exact rational sums") << ") in "
            << facts.refinement_seconds << " s\n  peak memory per rank " << std::setprecision(1)
            << peak << " MiB at most (";
  for (std::size_t q = 0; q < facts.peak_memory_mib.size(); ++q)
    std::cout << (q ? ", " : "") << facts.peak_memory_mib[q];
  std::cout << ")\n  wrote " << output << '\n' << std::defaultfloat;
}

// Rank 0's share of the file stands for all: the parts are of equal bytes.
distributed::ReadProgress reading_progress(const Options& options,
                                           const distributed::Communicator& communicator) {
  if (!options.progress || !communicator.is_root()) return {};
  return [](std::uint64_t read, std::uint64_t part) {
    std::cerr << "reading: " << (part == 0 ? 100 : read * 100 / part) << "% of rank 0's part\n";
  };
}

// Collective; returns whether the partition was written.
bool run_one(const std::string& path, const Options& options,
             const distributed::Communicator& communicator) {
  const Clock::time_point start = Clock::now();
  // The budget is each rank's: a header declaring more than a rank's share could fit is
  // refused before any rank reads its part.
  formats::ReadOptions read = options.read;
  read.memory_budget = cli::command_memory_budget();
  std::optional<distributed::OwnedModel> owned = distributed::read_aut_distributed(
      path, read, communicator, reading_progress(options, communicator));
  if (!owned) return false;
  distributed::RunFacts facts;
  facts.file = path;
  facts.model = owned->name;
  facts.ranks = communicator.size();
  facts.transitions = owned->num_edges;
  facts.load_seconds = seconds_since(start);
  const std::uint32_t states = owned->num_states;

  distributed::DistributedOptions refinement;
  refinement.rational_sums = options.rational_sums;
  const Clock::time_point refining = Clock::now();
  if (options.progress && communicator.is_root()) {
    std::fprintf(stderr, "read %s in %.2f s: %u states, %llu transitions\n", facts.model.c_str(),
                 facts.load_seconds, states, static_cast<unsigned long long>(facts.transitions));
  }
  refinement.on_round = [&](std::uint32_t round, std::uint64_t blocks) {
    maybe_kill_self(communicator.rank(), round);
    if (options.progress && communicator.is_root() && round > 0) {  // round - 1 is done
      std::fprintf(stderr, "round %u: %llu blocks, %.2f s\n", round - 1,
                   static_cast<unsigned long long>(blocks), seconds_since(refining));
    }
  };
  const distributed::DistributedPartition partition =
      distributed::refine_distributed(*owned, communicator, refinement);
  facts.refinement_seconds = seconds_since(refining);
  facts.rounds = partition.rounds;
  facts.exact_integer_sums = partition.exact_integer_sums;
  const std::optional<distributed::GatheredPartition> whole =
      distributed::gather_partition(*owned, partition, communicator);
  std::optional<model::ExplicitModel> quotient;
  if (options.format == "aut") quotient = distributed::gather_quotient(*owned, whole, communicator);
  owned.reset();
  for (const std::uint64_t kib : communicator.all_gather(peak_memory_kib()))
    facts.peak_memory_mib.push_back(static_cast<double>(kib) / 1024.0);

  bool written = true;
  if (communicator.is_root()) {
    const std::string output = output_for(options, path);
    std::string error;
    written = quotient ? formats::write_aut_file(*quotient, 0, output, error)
                       : distributed::write_partition_json(output, whole->partition, facts, error);
    if (!written)
      report_error(kProgram, "cannot write '" + output + "': " + error);
    else if (!options.quiet)
      print_summary(facts, states, partition.num_blocks, output);
  }
  return !communicator.any(!written);
}

// 0 when the models can be quotiented into options.output; otherwise the exit status, after
// rank 0 (`report`) has said why: 1 for a model it cannot read, 2 for outputs that cannot be
// told apart (bad usage). Checked before any work, so that no result is written and lost.
int check_models(const Options& options, bool report) {
  for (const std::string& model : options.models) {
    if (std::filesystem::path(model).extension() != ".aut") {
      if (report)
        report_error(model,
                     "oasisc-mpi reads mCRL2 .aut files; convert others with 'oasisc export " +
                         model + " --format aut -o MODEL.aut'");
      return 1;
    }
  }
  std::error_code code;
  if (options.models.size() > 1 && !std::filesystem::is_directory(options.output, code)) {
    if (report)
      report_error(kProgram, "with " + std::to_string(options.models.size()) +
                                 " models, -o must name an existing directory (one output per "
                                 "model)");
    return 2;
  }
  std::vector<std::string> outputs;
  for (const std::string& model : options.models)
    outputs.push_back(output_for(options, model));
  if (const auto shared = files::first_shared_output(outputs)) {
    if (report)
      report_error(kProgram, options.models[shared->first] + " and " +
                                 options.models[shared->second] + " would both be written to " +
                                 outputs[shared->first] +
                                 " (one output per model, named after it); quotient them in "
                                 "separate runs");
    return 2;
  }
  return 0;
}

}  // namespace

CommandRunner add_quotient_command(CLI::App& app, const distributed::Communicator& communicator) {
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand(
      "quotient", "The coarsest bisimulation of .aut models, spread over the ranks");
  command->footer(kFooter);
  command
      ->add_option("models", options->models, "mCRL2 .aut models (several: one output each in -o)")
      ->required();
  command
      ->add_option("-o,--output", options->output,
                   "The output file (a directory when several models are given: NAME.json or "
                   "NAME.aut in it)")
      ->required();
  command
      ->add_option("-f,--format", options->format,
                   "json: the partition, as 'oasisc quotient --format json --partition' writes it; "
                   "aut: the quotient MDP, as 'oasisc quotient --format aut' writes it")
      ->capture_default_str()
      ->check(CLI::IsMember({"json", "aut"}));
  cli::as_size(command
                   ->add_option("--max-input-size", options->read.max_bytes,
                                "Refuse files larger than this (bytes, or with a unit: 8G)")
                   ->capture_default_str());
  command
      ->add_option("--max-states", options->read.max_states,
                   "Refuse files whose header declares more states (by default only what "
                   "32-bit state numbers cannot hold: --memory-budget, per rank, bounds the "
                   "model)")
      ->capture_default_str()
      ->check(cli::whole_in(1, limits::kMaxStates));
  command->add_flag("--rational-sums", options->rational_sums,
                    "Add probabilities with GMP even when integers would be exact (for tests)");
  command->add_flag("--progress", options->progress,
                    "Report on stderr how the reading goes, then the blocks after each round");
  command->add_flag("-q,--quiet", options->quiet, "Print nothing on success");
  return [options, &communicator] {
    if (const int refused = check_models(*options, communicator.is_root())) return refused;
    bool ok = true;
    for (const std::string& model : options->models)
      ok = run_one(model, *options, communicator) && ok;
    return ok ? 0 : 1;
  };
}

}  // namespace oasis::mpi_cli
