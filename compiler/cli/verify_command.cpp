// `oasisc verify MODEL RESULT`: check independently that the partitions in RESULT are the
// coarsest bisimulations of MODEL's contexts, so that a quotient can be trusted without
// trusting the engine that computed it; likewise a catalog, schedulers, and a continuous
// model's controller and its bounds (by simulation).

#include <iostream>
#include <limits>
#include <memory>
#include <optional>

#include "cli/commands.hpp"
#include "cli/label_options.hpp"
#include "command_line/number_options.hpp"
#include "model/catalog_data.hpp"
#include "oasis/rt/catalog_file.hpp"
#include "oasis/rt/catalog_validation.hpp"
#include "oasis/rt/spec_hash.hpp"
#include "property/catalog_guarantees.hpp"
#include "support/error_report.hpp"
#include "text/printable_text.hpp"
#include "verify/continuous_check.hpp"
#include "verify/continuous_json_reader.hpp"
#include "verify/controller_check.hpp"
#include "verify/controller_reader.hpp"
#include "verify/discrete_catalog_check.hpp"
#include "verify/partition_result_reader.hpp"
#include "verify/scheduler_check.hpp"
#include "verify/scheduler_reader.hpp"
#include "verify/stated_cells_check.hpp"
#include "verify/verifier.hpp"

namespace oasis::cli {
namespace {

struct VerifyOptions {
  std::string model;
  std::string result;
  std::optional<double> p_correct;         // the catalog was compiled with --robust P
  verify::MonteCarloSettings monte_carlo;  // a controller file's bounds
  CommonOptions common;
};

int print_checks(const std::vector<verify::CatalogCheck>& checks);

// True when `view` was compiled from MODEL's very bytes (`hash`: of the bytes the front end
// or the reader parsed); otherwise says so.
bool compiled_from_model(const VerifyOptions& options, std::uint64_t hash,
                         const rt::CatalogView& view) {
  if (view.spec_hash == hash) return true;
  report_error(options.result, "the catalog was compiled from another spec (hash " +
                                   rt::spec_hash_text(view.spec_hash) + ", this one has " +
                                   rt::spec_hash_text(hash) + "); recompile it");
  return false;
}

// `verify MODEL CATALOG.bin`: the file loads (magic, checksum, structure), was compiled from
// this spec, and every item it carries holds (verify/discrete_catalog_check.hpp).
int verify_catalog(const VerifyOptions& options, const LoadedModel& loaded,
                   DiagnosticEngine& diagnostics) {
  const model::ExplicitModel& model = *loaded.model;
  const std::uint64_t hash = loaded.source_hash;
  const rt::LoadedCatalog catalog = rt::LoadedCatalog::from_file(options.result);
  if (!catalog.ok()) {
    std::cerr << catalog.error() << '\n';
    return 1;
  }
  const rt::CatalogView& view = catalog.view();
  if (!compiled_from_model(options, hash, view)) return 1;
  if (view.is_continuous()) {
    report_error(options.result, "a continuous catalog, but the model is explicit");
    return 1;
  }
  std::vector<verify::CatalogCheck> checks =
      verify::check_discrete_catalog(model, view, {.robust_p_correct = options.p_correct});
  // The stated properties, recomputed on the model's own states (catalog_guarantees.hpp).
  for (property::GuaranteeVerdict& verdict :
       property::check_guarantees(model, loaded.names, loaded.properties, view, diagnostics))
    checks.push_back({std::move(verdict.item), std::move(verdict.verdict), verdict.ok});
  return print_checks(checks);
}

// The checks of a continuous catalog, whichever file it came from (the binary file, loaded
// and validated, or the JSON, read back and validated).
int check_continuous_view(const VerifyOptions& options, const model::ModelIR& ir,
                          std::uint64_t hash, const rt::CatalogView& view,
                          const verify::StatedCells* stated = nullptr) {
  if (!compiled_from_model(options, hash, view)) return 1;
  if (!view.is_continuous()) {
    report_error(options.result, "an explicit model's catalog, but the spec is continuous");
    return 1;
  }
  std::vector<verify::CatalogCheck> checks = verify::check_continuous_catalog(ir, view);
  if (stated != nullptr) {
    for (verify::CatalogCheck& check : verify::check_stated_cells(ir, view, *stated))
      checks.push_back(std::move(check));
  }
  return print_checks(checks);
}

// `verify SPEC NAME.controller.json`: the controller file's structure against the spec, and
// its bounds against simulations of the true system (verify/controller_check.hpp).
int verify_controller(const VerifyOptions& options, const model::ModelIR& ir) {
  std::string error;
  const auto file =
      verify::read_controller_file(options.result, options.common.load.max_input_bytes, error);
  if (!file) {
    report_error(options.result, text::printable_message(error));
    return 1;
  }
  return print_checks(verify::check_controller(ir, *file, options.monte_carlo));
}

int verify_continuous(const VerifyOptions& options, const model::ModelIR& ir, std::uint64_t hash) {
  if (verify::is_controller_file(options.result, options.common.load.max_input_bytes))
    return verify_controller(options, ir);
  if (options.result.ends_with(".json")) {
    std::string error;
    verify::StatedCells stated;  // the JSON's own cells, checked against the partition
    auto data = verify::read_continuous_catalog_json(
        options.result, options.common.load.max_input_bytes, error, &stated);
    if (!data) {
      report_error(options.result, text::printable_message(error));
      return 1;
    }
    const rt::CatalogView view = data->view();
    if (!rt::validate(view, &error)) {
      report_error(options.result, "invalid catalog: " + text::printable_message(error));
      return 1;
    }
    return check_continuous_view(options, ir, hash, view, &stated);
  }
  const rt::LoadedCatalog catalog = rt::LoadedCatalog::from_file(options.result);
  if (!catalog.ok()) {
    std::cerr << catalog.error() << '\n';
    return 1;
  }
  return check_continuous_view(options, ir, hash, catalog.view());
}

// `verify MODEL SCHEDULERS.json`: each memoryless scheduler the file holds (oasisc query
// --scheduler) is optimal for its property, checked exactly (verify/scheduler_check.hpp).
int verify_schedulers(const VerifyOptions& options, const model::ExplicitModel& model) {
  std::string error;
  const auto file =
      verify::read_scheduler_file(options.result, options.common.load.max_input_bytes, error);
  if (!file) {
    report_error(options.result, text::printable_message(error));
    return 1;
  }
  return print_checks(verify::check_schedulers(
      model, *file, {.max_number_bits = options.common.load.max_number_bits}));
}

int print_checks(const std::vector<verify::CatalogCheck>& checks) {
  bool all_hold = true;
  for (const verify::CatalogCheck& check : checks) {
    // Names in a verdict come from the catalog file: quoted as every message quotes input.
    std::cout << text::printable_message(check.item + ": " + check.verdict) << '\n';
    all_hold = all_hold && check.ok;
  }
  return all_hold ? 0 : 1;
}

int run_verify(const VerifyOptions& options) {
  SourceManager sources;
  DiagnosticEngine diagnostics(sources, std::cerr, options.common.max_errors);
  auto loaded =
      load_model(options.model, sources, diagnostics, effective_load_options(options.common));
  if (!loaded || diagnostics.has_errors()) return 1;
  if (!loaded->model) return verify_continuous(options, *loaded->ir, loaded->source_hash);
  const model::ExplicitModel& model = *loaded->model;
  std::string error;
  if (options.result.ends_with(".controller.json")) {
    report_error(options.result,
                 "a controller file, but the model is not a continuous spec with an objective");
    return 1;
  }
  // A compiled binary catalog (oasisc compile): everything it carries is checked.
  if (options.result.ends_with(".bin")) return verify_catalog(options, *loaded, diagnostics);
  if (verify::is_scheduler_file(options.result, options.common.load.max_input_bytes))
    return verify_schedulers(options, model);
  const auto result = verify::read_partition_result(options.result, model,
                                                    options.common.load.max_input_bytes, error);
  if (!result) {
    report_error(options.result, text::printable_message(error));
    return 1;
  }
  if (result->approximate) {
    report_note(options.result,
                "the partitions were computed with --epsilon; they are checked exactly, so "
                "differences below epsilon fail");
  }

  const auto label_class = respected_label_classes(model, result->respected_labels, options.result);
  if (!label_class) return 1;
  bool all_hold = true;
  for (const verify::ContextPartition& entry : result->contexts) {
    const std::string& name = model.contexts[entry.context].name;
    const verify::VerificationResult verdict = verify::verify_partition(
        model, entry.context, entry.partition, *label_class, result->unlabelled_choices);
    if (verdict.ok()) {
      std::cout << "context " << name << ": bisimulation"
                << (result->unlabelled_choices ? " (unlabelled choices)" : "") << " and coarsest ("
                << entry.partition.num_blocks
                << (entry.partition.num_blocks == 1 ? " block)\n" : " blocks)\n");
      continue;
    }
    all_hold = false;
    std::cout << "context " << name << ": FAILED (" << verify::kind_name(verdict.violation->kind)
              << "): " << verdict.violation->message << '\n';
  }
  for (std::size_t c = 0; c < model.contexts.size(); ++c) {
    bool listed = false;
    for (const verify::ContextPartition& entry : result->contexts)
      listed = listed || entry.context == c;
    if (!listed)
      std::cout << "context " << model.contexts[c].name << ": not in RESULT, not checked\n";
  }
  return all_hold ? 0 : 1;
}

void add_monte_carlo_options(CLI::App& command, verify::MonteCarloSettings& settings) {
  command
      .add_option("--samples", settings.samples,
                  "Controller files: simulated runs per tested cell (M)")
      ->capture_default_str()
      ->check(whole_in(1, 1'000'000'000));
  command.add_option("--cells", settings.cells, "Controller files: cells tested (K)")
      ->capture_default_str()
      ->check(whole_in(1, 1'000'000'000));
  command
      .add_option("--confidence", settings.confidence,
                  "Controller files: the probability that a sound file passes (1 - delta)")
      ->capture_default_str()
      ->check(real_in(RealBounds{0.0, 1.0, true, true}));
  command
      .add_option("--seed", settings.seed,
                  "Controller files: the seed of the tested cells, their points and the runs")
      ->capture_default_str()
      ->check(whole_in(0, std::numeric_limits<std::uint64_t>::max()));
  command
      .add_option("--max-steps", settings.max_steps,
                  "Controller files: steps after which an unbounded objective's run that is "
                  "still undecided counts as a failure (H)")
      ->capture_default_str()
      ->check(whole_in(1, 1'000'000'000));
}

}  // namespace

CommandRunner add_verify_command(CLI::App& app) {
  auto options = std::make_shared<VerifyOptions>();
  CLI::App* command = app.add_subcommand(
      "verify", "Check a compiled catalog (or a quotient's partitions) against its model");
  command->footer(
      "RESULT is a catalog NAME.bin written by 'oasisc compile', the JSON of 'oasisc\n"
      "quotient --format json --partition', a scheduler file of 'oasisc query\n"
      "--scheduler' (JSON with a \"schedulers\" key), or a controller file\n"
      "NAME.controller.json of 'oasisc compile'. The checker shares no code with the\n"
      "compiler's quotient, policy, model checker, guarantees or emitters; it compares with\n"
      "the model in exact arithmetic (a controller's bounds: by simulation).\n\n"
      "For a catalog it checks, and prints one line each:\n"
      "  - the file: magic, format, checksum, structure; compiled from this very spec;\n"
      "  - names: the model's name, actions, states and contexts, in order;\n"
      "  - switching and prior: equal to the spec's (an imported model: the trivial one);\n"
      "  - observation model: the spec's 'observation' block (kind, noise or confusion\n"
      "    matrix, what the reward follows), or none when the spec has none; a catalog\n"
      "    compiled with --robust P is checked with --robust P here too;\n"
      "  - per context: the partition is a bisimulation (Definition 1) and the coarsest;\n"
      "    block rewards, R^Z, the quotient's transitions and the robust section equal the\n"
      "    model's; the policy is optimal for its quotient, by policy evaluation, within\n"
      "    tol = 1e-6 max(1, max|V|) (discounted: a Bellman residual that proves it;\n"
      "    horizon H: the first step of an optimal H-step plan), and the values are within\n"
      "    tol of the policy's. Doubles must be the exact values up to rounding (2^-50\n"
      "    relative).\n"
      "For a continuous spec's catalog (NAME.bin, or NAME.json read back into the same\n"
      "form): the names, switching and prior; per context the variables it attends to\n"
      "(recomputed), the domain, the reward constant on every cell and equal to its\n"
      "block's, the locator against plain membership (grid or BSP of polytope cells;\n"
      "polytope cells in 1-D and 2-D also clipped as polygons whose areas sum to the\n"
      "domain's); and, when the file has the transition rows (compile\n"
      "--with-transitions), sampled cells' rows recomputed from the spec at their centres\n"
      "and corners and within the catalog's epsilon in total variation, and the policy\n"
      "and values as above.\n"
      "For a partition JSON it checks the partitions only. The coarsest check is\n"
      "quadratic in the number of blocks at worst.\n"
      "For a scheduler file, per memoryless scheduler of Pmax=? or Pmin=? [F T] or\n"
      "[phi U T] (T, phi: quoted labels with !, &, |; other properties are not checked):\n"
      "every state named once, every action enabled, null only where the choice cannot\n"
      "matter; the value of the chain it induces, solved exactly (GMP rationals); and\n"
      "optimality by a certificate: no action improves on that value anywhere (for Pmin,\n"
      "also 0 wherever some scheduler avoids the target forever). It prints the value in\n"
      "the initial state.\n"
      "For a controller file NAME.controller.json (a continuous spec with an 'objective';\n"
      "or any JSON whose \"format\" is \"oasis-controller\"): the model's name and\n"
      "variables; the grid's breakpoints, each the nearest double to the spec's exact one;\n"
      "the inputs and actions; the objective; 0 <= lower <= upper <= 1 per cell; the\n"
      "controller's shape and action indices. Then a Monte-Carlo check of the bounds: in\n"
      "--cells K cells (a third with lower > 0.05, a third with upper < 0.95, the rest any),\n"
      "from a random point of each, --samples M runs of the true system (the spec's map in\n"
      "doubles, its noise) under the controller; each cell's estimate p must satisfy\n"
      "lower - t <= p <= upper + t, t = sqrt(ln(2K / (1 - confidence)) / (2M)) (Hoeffding,\n"
      "a union bound over the K cells), so a sound file fails with probability at most\n"
      "1 - confidence. A run that leaves the grid's box while in the safe set counts as a\n"
      "failure (the pessimistic reading; the report says how many), and so does an\n"
      "unbounded run still undecided after --max-steps.\n\n"
      "Exit status: 0 everything holds, 1 a failure or a bad MODEL or RESULT.\n\n"
      "Examples:\n"
      "  oasisc compile specs/discrete_tracking.oasis -o out\n"
      "  oasisc verify specs/discrete_tracking.oasis out/discrete_tracking.bin\n"
      "  oasisc quotient specs/discrete_tracking.oasis --format json --partition -o r.json\n"
      "  oasisc verify specs/discrete_tracking.oasis r.json\n"
      "  oasisc query two_dice.nm --prop 'Pmax=? [F \"seven\"]' --scheduler s.json\n"
      "  oasisc verify two_dice.nm s.json\n"
      "  oasisc compile vdp.oasis -o out\n"
      "  oasisc verify vdp.oasis out/van_der_pol.controller.json --samples 4000");
  command
      ->add_option("model", options->model,
                   "Spec (.oasis), PRISM program (.pm, .nm, .prism) or model (.aut, .tra) file")
      ->required();
  command
      ->add_option(
          "result", options->result,
          "JSON written by 'oasisc quotient --partition' or 'oasisc query --scheduler', a "
          "catalog NAME.bin written by 'oasisc compile' (refused if damaged or compiled from "
          "another spec), or a controller file NAME.controller.json")
      ->required();
  command
      ->add_option("--robust", options->p_correct,
                   "The catalog was compiled with --robust P: expect its symmetric observation "
                   "model with p_correct P instead of the spec's")
      ->check(real_in(closed(0.0, 1.0)));
  add_monte_carlo_options(*command, options->monte_carlo);
  add_common_options(*command, options->common);
  return [options] { return run_verify(*options); };
}

}  // namespace oasis::cli
