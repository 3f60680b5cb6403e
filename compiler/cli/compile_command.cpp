// `oasisc compile SPEC -o DIR`: the catalog of a spec, as a directory of files that changes
// as one unit (support/staged_directory.hpp). `-o -` writes a catalog of one file (one
// format, one context for dot and svg) to standard output instead, and reports on stderr.

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <iostream>
#include <memory>
#include <mutex>
#include <set>
#include <sstream>
#include <thread>

#include "cli/commands.hpp"
#include "codegen/catalog_files.hpp"
#include "codegen/controller_json.hpp"
#include "command_line/memory_option.hpp"
#include "command_line/number_options.hpp"
#include "command_line/output_names.hpp"
#include "model/catalog_data.hpp"
#include "model/enclosure.hpp"
#include "oasis/rt/catalog_sections.hpp"
#include "oasis/rt/spec_hash.hpp"
#include "pipeline/continuous_catalog.hpp"
#include "pipeline/continuous_catalog_data.hpp"
#include "pipeline/continuous_options.hpp"
#include "pipeline/discrete_catalog.hpp"
#include "pipeline/guarantee_compile.hpp"
#include "property/catalog_guarantees.hpp"
#include "support/atomic_file.hpp"
#include "support/error_report.hpp"
#include "support/limits.hpp"
#include "support/staged_directory.hpp"
#include "support/text.hpp"

namespace oasis::cli {
namespace {

namespace fs = std::filesystem;

// The formats, the C++ files' basename, the spec and --with-transitions: what the writers
// of codegen/catalog_files.hpp read.
struct CompileOptions : codegen::CatalogFileOptions {
  std::string output;  // default: the spec's file name without its extension
  std::optional<double> p_correct;
  pipeline::TargetFlags target;  // continuous: --epsilon and --max-cells, when given
  bool no_attention = false;
  std::string grid_rows = "auto";  // --grid-rows
  unsigned jobs = 0;
  CommonOptions common;
};

// "0.1": a default as --help shows it.
std::string plain_number(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

// On `stream`: stdout, or stderr when the catalog itself goes to standard output.
void print_continuous_summary(const pipeline::ContinuousCatalog& catalog, std::FILE* stream) {
  for (const pipeline::ContinuousAbstraction& a : catalog.abstractions) {
    std::string attends;
    for (const std::string& name : a.axis_names)
      attends += (attends.empty() ? "" : ", ") + name;
    const double seconds =
        a.seconds.grid + a.seconds.finite_mdp + a.seconds.bisimulation + a.seconds.policy;
    std::fprintf(stream,
                 "context %s: attends to %s; %zu cells, %u blocks, epsilon %.4g%s (%.2f s)\n",
                 a.context.c_str(), attends.c_str(), a.num_cells(), a.num_blocks,
                 pipeline::bound_as_double(a.epsilon), a.exact() ? " (exact)" : "", seconds);
    if (!a.met) {
      std::fprintf(stream,
                   "  note: the cell budget (--max-cells) stopped the refinement above the "
                   "target epsilon\n");
    }
  }
}

// What each context's policy and the optimum give the spec's properties, one line each.
void print_guarantees(const model::CatalogData& catalog, std::FILE* stream) {
  const auto value = [](const double* bounds, const std::string& exact) {
    if (!exact.empty()) return exact;
    return "[" + shortest_double(bounds[0]) + ", " + shortest_double(bounds[1]) + "]";
  };
  for (const model::AbstractionData& a : catalog.abstractions) {
    for (std::size_t k = 0; k < catalog.properties.size(); ++k) {
      const double* bounds = a.guarantee.data() + k * rt::kGuaranteeFields;
      std::fprintf(stream, "context %s: %s = %s under its policy, %s at the optimum\n",
                   a.context.c_str(), catalog.properties[k].name.c_str(),
                   value(bounds + rt::kPolicyLower, a.guarantee_exact[k * 2]).c_str(),
                   value(bounds + rt::kOptimumLower, a.guarantee_exact[k * 2 + 1]).c_str());
    }
  }
}

// The bounds of a compiled objective, summed up: what a reader wants before opening the file.
void print_objective_summary(const model::ModelIR& ir, const pipeline::GuaranteeResult& result,
                             std::FILE* stream) {
  const guarantee::Synthesis& s = result.synthesis;
  const std::size_t cells = result.grid.cells;
  std::fprintf(stream,
               "objective: %zu cells x %zu actions, %llu interval entries, %llu distinct rows "
               "(%.2f s)\n",
               cells, result.actions.size(), static_cast<unsigned long long>(result.entries),
               static_cast<unsigned long long>(result.distinct_rows), result.abstraction_seconds);
  const std::string sweeps = std::to_string(s.sweeps + s.evaluation_sweeps);
  std::fprintf(stream,
               "  bounds: lower mean %.6f, upper mean %.6f, largest gap %.3g; %s after %s "
               "sweeps (%.2f s)\n",
               s.lower_mean(), s.upper_mean(), s.largest_gap, s.stop_reason.c_str(), sweeps.c_str(),
               result.synthesis_seconds);
  if (!s.lower_method.empty()) {
    std::fprintf(stream, "  lower bound: %s; upper bound: %s (%llu sweeps); %llu linear solves\n",
                 s.lower_method.c_str(), s.upper_method.c_str(),
                 static_cast<unsigned long long>(s.upper_sweeps),
                 static_cast<unsigned long long>(s.policy_rounds));
  }
  // The cell at the domain's centre: where benchmark tables usually quote "the" value.
  std::size_t centre = 0;
  for (std::size_t i = 0; i < result.grid.dimension(); ++i)
    centre += result.grid.intervals(i) / 2 * result.grid.strides[i];
  std::fprintf(stream, "  at the centre cell (%s): [%.6f, %.6f]\n",
               pipeline::describe_cell(result.grid, ir, centre).c_str(), s.lower[centre],
               s.upper[centre]);
}

// A continuous model with an objective: the controller and its bounds, as NAME.controller.json.
bool compile_objective(const CompileOptions& options, const model::ModelIR& ir,
                       DiagnosticEngine& diagnostics, codegen::OutputSet& out, std::string& error) {
  pipeline::GuaranteeOptions build;
  build.jobs = options.jobs == 0 ? std::max(1u, std::thread::hardware_concurrency()) : options.jobs;
  build.synthesis.jobs = build.jobs;
  // The rows take most of the memory: refuse them up front when they would not fit the budget
  // (half of it: the sweeps need their own tables, and the output its buffers).
  build.memory_budget = command_memory_budget() / 2;
  if (effective_load_options(options.common).progress) {
    build.progress = [](const std::string& line) {
      std::fprintf(stderr, "oasisc: %s\n", line.c_str());
    };
    build.synthesis.progress = [](std::uint64_t sweep, double gap) {
      if (sweep % 100 == 0)
        std::fprintf(stderr, "oasisc: sweep %llu, largest change %.3g\n",
                     static_cast<unsigned long long>(sweep), gap);
    };
  }
  std::optional<pipeline::GuaranteeResult> result;
  try {
    result = pipeline::compile_guarantee(ir, build);
  } catch (const model::EnclosureError& refusal) {
    diagnostics.error(refusal.where, refusal.what());
    return false;
  } catch (const std::invalid_argument& refusal) {
    diagnostics.error(ir.grid_range, refusal.what());
    return false;
  } catch (const std::length_error& refusal) {
    diagnostics.error(ir.grid_range, refusal.what());
    return false;
  }
  print_objective_summary(ir, *result, out.to_standard_output() ? stderr : stdout);
  return out.write_with(
      ir.name + ".controller.json",
      [&](AtomicFile& file) {
        codegen::JsonWriter writer([&file](std::string_view piece) { file.append(piece); });
        codegen::write_controller_json(writer, ir, *result);
      },
      error);
}

int run_compile(CompileOptions options) {
  SourceManager sources;
  DiagnosticEngine diagnostics(sources, std::cerr, options.common.max_errors);
  auto loaded =
      load_model(options.spec, sources, diagnostics, effective_load_options(options.common));
  if (!loaded || diagnostics.has_errors()) return 1;
  const bool continuous = !loaded->model;
  const bool objective = continuous && loaded->ir->guarantee.has_value();
  if (objective && !options.formats.empty() &&
      (options.formats.size() != 1 || options.formats.front() != "json")) {
    report_error(options.spec,
                 "a model with an objective compiles to its controller's JSON "
                 "(docs/guarantees.md): --format json, or no --format");
    return 1;
  }
  if (objective) {
    // The catalog's options mean nothing on an objective's grid: say so rather than ignore them.
    const char* catalog_option = options.no_attention            ? "--no-attention"
                                 : options.target.epsilon        ? "--epsilon"
                                 : options.target.max_cells      ? "--max-cells"
                                 : options.with_transitions      ? "--with-transitions"
                                 : options.p_correct.has_value() ? "--robust"
                                                                 : nullptr;
    if (catalog_option != nullptr) {
      report_error(options.spec, std::string(catalog_option) +
                                     " is for catalogs; a model with an objective is solved on "
                                     "its spec's 'grid' (docs/guarantees.md)");
      return 1;
    }
    options.formats = {"json"};
  }
  if (options.formats.empty()) options.formats = codegen::default_catalog_formats(continuous);
  const char* refused = codegen::unfitting_drawing(options, continuous);
  if (refused != nullptr) {
    report_error(options.spec,
                 std::string("--format ") + refused + " draws " +
                     (continuous ? "explicit quotients; use svg for a continuous spec"
                                 : "continuous abstractions; use dot for a discrete model"));
    return 1;
  }
  if (continuous && options.p_correct) {
    report_error(options.spec, "--robust needs explicit states (a discrete model)");
    return 1;
  }
  if (!continuous && options.target.epsilon) {
    // A catalog claims an exact bisimulation, which `verify` checks exactly; a rounded
    // quotient of a noisy model would be refused by it, so compile never makes one.
    report_warning(options.spec,
                   "--epsilon is the error bound of continuous specs and is ignored here: a "
                   "discrete catalog is an exact bisimulation ('oasisc quotient --epsilon E' "
                   "explores a rounded quotient of a model with noisy probabilities)");
  }
  const std::uint64_t hash = loaded->source_hash;
  if (options.output.empty()) options.output = fs::path(options.spec).stem().string();
  const bool to_standard_output = options.output == "-";
  // Refused before the build when the formats alone decide it (the context count may not).
  if (to_standard_output && !codegen::one_file_error(options, 1).empty()) {
    report_error(kProgram, codegen::one_file_error(options, 1));
    return 2;
  }
  StagedDirectory directory;
  std::string error;
  if (!to_standard_output && !directory.open(options.output, error)) {
    report_error(options.output, error);
    return 1;
  }
  codegen::OutputSet out(to_standard_output ? std::string() : directory.staging_path());
  bool written = false;
  if (objective) {
    if (!compile_objective(options, *loaded->ir, diagnostics, out, error)) {
      if (diagnostics.has_errors()) return 1;
      report_error(options.output, error);
      return 1;
    }
    written = true;
  } else if (continuous) {
    pipeline::ContinuousCatalogOptions build;
    build.abstraction.target = pipeline::continuous_target(*loaded->ir, options.target);
    build.abstraction.attention = !options.no_attention;
    build.abstraction.grid_rows = options.grid_rows == "product" ? pipeline::GridRows::kProduct
                                  : options.grid_rows == "materialised"
                                      ? pipeline::GridRows::kMaterialised
                                      : pipeline::GridRows::kAutomatic;
    build.abstraction.keep_rows = options.with_transitions;
    build.jobs = options.jobs;
    std::mutex stderr_lock;
    // Said at once, whatever --progress says: the stages after the partition can be long.
    build.abstraction.warn = [&stderr_lock](const std::string& context,
                                            const std::string& warning) {
      const std::lock_guard lock(stderr_lock);
      std::ostringstream text;  // the context in double quotes, as this warning always had it
      text << "context " << std::quoted(context) << ": " << warning;
      report_warning(kProgram, text.str());
    };
    if (effective_load_options(options.common).progress) {
      build.abstraction.progress = [&stderr_lock](const std::string& context,
                                                  const std::string& done, double seconds) {
        const std::lock_guard lock(stderr_lock);
        std::fprintf(stderr, "oasisc: %s: %s (%.2f s)\n", context.c_str(), done.c_str(), seconds);
      };
    }
    const auto catalog = pipeline::build_continuous_catalog(*loaded->ir, hash, build, error);
    if (!catalog) {
      report_error(options.spec, error);
      return 1;
    }
    print_continuous_summary(*catalog, to_standard_output ? stderr : stdout);
    written = codegen::write_continuous_catalog(options, *catalog, out, error);
  } else {
    pipeline::BuildOptions build;
    build.catalog.p_correct = options.p_correct;
    build.abstraction.jobs = options.jobs;
    auto catalog = pipeline::build_catalog(*loaded->model, hash, build, error);
    if (!catalog) {
      report_error(options.spec, error);
      return 1;
    }
    if (!property::state_guarantees(*loaded->model, loaded->names, loaded->properties, *catalog,
                                    diagnostics))
      return 1;
    print_guarantees(*catalog, to_standard_output ? stderr : stdout);
    written = codegen::write_discrete_catalog(options, *catalog, out, error);
  }
  if (!written ||
      (!to_standard_output && !directory.commit(codegen::marker_text(options, hash, out), error))) {
    report_error(to_standard_output ? kProgram : std::string_view(options.output), error);
    return 1;
  }
  if (to_standard_output) return 0;
  for (const std::string& name : out.names())
    std::cout << "wrote " << (fs::path(options.output) / name).string() << '\n';
  return 0;
}

}  // namespace

CommandRunner add_compile_command(CLI::App& app) {
  auto options = std::make_shared<CompileOptions>();
  CLI::App* command = app.add_subcommand(
      "compile", "Compile a spec into a catalog: the abstraction and policy of every context");
  command->footer(
      "Discrete specs and imported models: for every context the coarsest bisimulation\n"
      "quotient (see 'oasisc quotient') and a policy solved on it (docs/policies.md).\n"
      "Continuous specs: for every context the variables it attends to, a partition of\n"
      "them refined until every transition row is within --epsilon of the truth (a sound\n"
      "bound, docs/geometry.md), the quotient of that finite MDP and its policy. The\n"
      "partition is a grid where the context allows it (box rewards, moves along single\n"
      "axes, uniform or Gaussian disturbances), else convex polytope cells in a BSP,\n"
      "computed exactly (CGAL's linear programs); --progress shows each stage.\n"
      "Continuous specs with an 'objective' (docs/guarantees.md): an interval MDP on the\n"
      "spec's grid and a controller with, per cell, a proven lower bound on the true\n"
      "system's probability of meeting the objective and an upper bound no controller\n"
      "beats, written as NAME.controller.json (-j 2: the two bounds on two threads).\n\n"
      "DIR (default: the spec's name, e.g. ./discrete_tracking) is written as one unit: the\n"
      "whole new set of files replaces the whole old one, also if compile is killed. DIR\n"
      "must be new, empty, or written by an earlier compile (marked by .oasisc-output).\n"
      "-o - writes a catalog of one file to standard output instead: one --format (bin,\n"
      "json, or dot/svg for a spec with one context); the report goes to stderr.\n"
      "  NAME.bin           the binary catalog the runtime loads (rt::LoadedCatalog)\n"
      "  NAME.json          the same for people and tools (continuous: docs/geometry.md)\n"
      "  NAME.CONTEXT.dot   each explicit abstraction for Graphviz (bold: the policy)\n"
      "  NAME.CONTEXT.svg   each continuous abstraction as a picture\n"
      "  NAME_catalog.hpp/.cpp  (--format cpp) C++ tables to link: NAME::catalog()\n"
      "Default formats: bin,json,dot (discrete), bin,json,svg (continuous).\n\n"
      "Observation model: a discrete spec's 'observation' block (docs/spec-language.md) puts\n"
      "the robust section, what the runtime's robust filter needs, into every carrier: the\n"
      "sensor's noise or confusion matrix, what the reward follows, and every context's\n"
      "full-state transitions. --robust P adds that section with a symmetric model that\n"
      "reports the true state with probability P, overriding the spec's noise (p_correct =\n"
      "1 - noise; the spec's 'reward follows' stays); verify such a catalog with --robust P.\n\n"
      "Examples:\n"
      "  oasisc compile specs/discrete_tracking.oasis -o out\n"
      "  oasisc verify specs/discrete_tracking.oasis out/discrete_tracking.bin\n"
      "  oasisc compile specs/arch/bas4d.oasis -o out/bas4d\n"
      "  oasisc verify specs/arch/bas4d.oasis out/bas4d/bas4d.controller.json\n"
      "  oasisc compile specs/go1_treat.oasis -o go1 --format bin,json,cpp,svg --epsilon 0.1\n"
      "  oasisc compile specs/go1_treat.oasis -o go1 --with-transitions   # rows for analysis\n"
      "  oasisc verify specs/go1_treat.oasis go1/go1_treat.json");
  command
      ->add_option("spec", options->spec,
                   "Spec (.oasis), PRISM program (.pm, .nm, .prism) or model (.aut, .tra) file")
      ->required();
  command->add_option("-o,--output", options->output,
                      "Output directory (default: the spec's file name without extension); "
                      "'-': the one file of a single --format on standard output");
  command
      ->add_option("-f,--format", options->formats,
                   "Formats: bin, json, dot, svg, cpp (default: bin,json,dot or bin,json,svg)")
      ->delimiter(',')
      ->check(CLI::IsMember({"bin", "json", "dot", "svg", "cpp"}));
  command
      ->add_option("--basename", options->basename,
                   "File name (without extension) of the C++ output, inside the output folder")
      ->check(plain_file_name());  // never a path: compile writes nowhere else
  command
      ->add_option("--robust", options->p_correct,
                   "Add the robust filter's section with this sensor accuracy P = 1 - noise "
                   "(discrete), overriding the spec's observation noise")
      ->check(real_in(closed(0.0, 1.0)));
  command
      ->add_option("--epsilon", options->target.epsilon,
                   "Continuous: the error bound every transition row must meet (default: the "
                   "spec's 'epsilon', else " +
                       plain_number(pipeline::kDefaultEpsilon) + ")")
      ->check(real_in(RealBounds{0.0, 1.0, true, false}));
  command
      ->add_option("--max-cells", options->target.max_cells,
                   "Continuous: cells per context at most (default: the spec's 'max_cells', else " +
                       std::to_string(pipeline::kDefaultGridCells) + " on a grid, " +
                       std::to_string(pipeline::kDefaultPolytopeCells) + " polytope cells)")
      ->check(whole_in(1, static_cast<std::uint64_t>(limits::kMaxCellsSetting)));
  command->add_flag("--no-attention", options->no_attention,
                    "Continuous: partition every variable (the no-attention baseline)");
  command->add_flag("--with-transitions", options->with_transitions,
                    "Continuous: also write the quotient's transition rows (large)");
  command
      ->add_option("--grid-rows", options->grid_rows,
                   "Continuous: 'product' keeps each row compact (the grid path: per-axis "
                   "rows; the polytope path: the subtrees and cut cells of its tree walk), "
                   "proves by invariants that no two cells are bisimilar and solves on that "
                   "form (memory grows with the compact rows, not the edges); 'materialised' "
                   "writes every row out for the exact refinement; 'auto' keeps rows compact "
                   "above " +
                       std::to_string(pipeline::kProductRowsAbove) +
                       " edges per context (docs/geometry.md)")
      ->capture_default_str()
      ->check(CLI::IsMember({"auto", "product", "materialised"}));
  command->add_option("-j,--jobs", options->jobs, "Contexts abstracted in parallel (0: all cores)")
      ->capture_default_str()
      ->check(whole_in(0, limits::kMaxJobs));
  add_common_options(*command, options->common);
  return [options] { return run_compile(*options); };
}

}  // namespace oasis::cli
