// `oasisc verify MODEL RESULT`: check independently that the partitions in RESULT are the
// coarsest bisimulations of MODEL's contexts, so that a quotient can be trusted without
// trusting the engine that computed it.

#include <iostream>
#include <memory>

#include "cli/catalog_result_reader.hpp"
#include "cli/commands.hpp"
#include "cli/partition_result_reader.hpp"
#include "codegen/catalog_data.hpp"
#include "verify/verifier.hpp"

namespace oasis::cli {
namespace {

struct VerifyOptions {
  std::string model;
  std::string result;
  CommonOptions common;
};

int run_verify(const VerifyOptions& options) {
  SourceManager sources;
  DiagnosticEngine diagnostics(sources, std::cerr, options.common.max_errors);
  auto loaded =
      load_model(options.model, sources, diagnostics, effective_load_options(options.common));
  if (!loaded || diagnostics.has_errors()) return 1;
  if (!loaded->model) {
    std::cerr << options.model
              << ": error: a continuous model has no explicit states to "
                 "verify a partition of\n";
    return 1;
  }
  const model::ExplicitModel& model = *loaded->model;
  std::string error;
  // A compiled binary catalog (oasisc compile) or a quotient --partition JSON result.
  const bool catalog = options.result.size() > 4 && options.result.ends_with(".bin");
  const auto result =
      catalog ? read_catalog_partitions(options.result, model,
                                        codegen::spec_hash_of_file(options.model), error)
              : read_partition_result(options.result, model, error);
  if (!result) {
    std::cerr << options.result << ": error: " << error << '\n';
    return 1;
  }
  if (result->approximate) {
    std::cerr << options.result
              << ": note: the partitions were computed with --epsilon; they "
                 "are checked exactly, so differences below epsilon fail\n";
  }

  bool all_hold = true;
  for (const ContextPartition& entry : result->contexts) {
    const std::string& name = model.contexts[entry.context].name;
    const verify::VerificationResult verdict =
        verify::verify_partition(model, entry.context, entry.partition);
    if (verdict.ok()) {
      std::cout << "context " << name << ": bisimulation and coarsest ("
                << entry.partition.num_blocks << " blocks)\n";
      continue;
    }
    all_hold = false;
    std::cout << "context " << name << ": FAILED (" << verify::kind_name(verdict.violation->kind)
              << "): " << verdict.violation->message << '\n';
  }
  for (std::size_t c = 0; c < model.contexts.size(); ++c) {
    bool listed = false;
    for (const ContextPartition& entry : result->contexts)
      listed = listed || entry.context == c;
    if (!listed)
      std::cout << "context " << model.contexts[c].name << ": not in RESULT, not checked\n";
  }
  return all_hold ? 0 : 1;
}

}  // namespace

CommandRunner add_verify_command(CLI::App& app) {
  auto options = std::make_shared<VerifyOptions>();
  CLI::App* command = app.add_subcommand(
      "verify", "Check that the partitions in a quotient RESULT are the coarsest bisimulations");
  command->footer(
      "For every context listed in RESULT, checks exactly (rational arithmetic) that its\n"
      "partition is\n"
      "  - a bisimulation (Definition 1): states of a block enable the same actions, have\n"
      "    the same reward R(s, a) for each enabled action, and reach every block with the\n"
      "    same probability under each enabled action (states with no enabled action\n"
      "    must have the same state reward R(s)); and\n"
      "  - the coarsest one: no two blocks are bisimilar (a naive refinement of the quotient\n"
      "    ends with one class per block).\n"
      "The checker shares no code with the engine of 'oasisc quotient'. It prints one line\n"
      "per context: 'bisimulation and coarsest', or the first violation with its states,\n"
      "action and blocks (numbered from 0 in the order RESULT lists them). It is simple\n"
      "rather than fast: the coarsest check is quadratic in the number of blocks at worst.\n\n"
      "RESULT is the JSON of 'oasisc quotient --format json --partition':\n"
      "  {\"contexts\": [{\"name\": \"object_at_s3\", \"partition\": [[\"s1\", \"s2\"], "
      "[\"s3\"]]}]}\n"
      "States are names as oasisc prints them (\"s1\", \"(x=1,y=0)\") or indices (imported\n"
      "models). Every state must be in exactly one block.\n\n"
      "Exit status: 0 every listed context holds, 1 a violation or a bad MODEL or RESULT.\n\n"
      "Example:\n"
      "  oasisc quotient specs/discrete_tracking.oasis --format json --partition -o r.json\n"
      "  oasisc verify specs/discrete_tracking.oasis r.json");
  command->add_option("model", options->model, "Spec (.oasis) or model (.aut, .tra) file")
      ->required();
  command
      ->add_option(
          "result", options->result,
          "JSON written by 'oasisc quotient --partition', or a catalog NAME.bin written by "
          "'oasisc compile' (refused if damaged or compiled from another spec)")
      ->required();
  add_common_options(*command, options->common);
  return [options] { return run_verify(*options); };
}

}  // namespace oasis::cli
