// `oasisc compile SPEC -o DIR`: the catalog of a spec, as files.

#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>

#include "cli/commands.hpp"
#include "codegen/binary_catalog.hpp"
#include "codegen/catalog_data.hpp"
#include "codegen/cpp_catalog.hpp"
#include "codegen/dot_catalog.hpp"
#include "codegen/json_catalog.hpp"
#include "support/atomic_file.hpp"

namespace oasis::cli {
namespace {

struct CompileOptions {
  std::string spec;
  std::string output = ".";
  std::vector<std::string> formats{"bin", "json", "dot"};
  std::string basename;  // of the C++ files; default NAME_catalog
  std::optional<double> p_correct;
  CommonOptions common;
};

bool write_text(const std::string& path, const std::string& text) {
  AtomicFile file;
  std::string error;
  if (!file.open(path, error) || (file.append(text), !file.commit(error))) {
    std::cerr << path << ": error: " << error << '\n';
    return false;
  }
  std::cout << "wrote " << path << '\n';
  return true;
}

bool emit(codegen::CatalogData& catalog, const CompileOptions& options) {
  const std::filesystem::path dir(options.output);
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) {
    std::cerr << options.output << ": error: cannot create directory: " << ec.message() << '\n';
    return false;
  }
  for (const std::string& format : options.formats) {
    const std::string base = (dir / catalog.name).string();
    if (format == "bin") {
      std::string error;
      if (!codegen::write_binary_catalog(catalog, base + ".bin", error)) {
        std::cerr << base << ".bin: error: " << error << '\n';
        return false;
      }
      std::cout << "wrote " << base << ".bin\n";
    } else if (format == "json") {
      if (!write_text(base + ".json", codegen::catalog_json(catalog).dump(2) + "\n")) return false;
    } else if (format == "cpp") {
      const std::string basename =
          options.basename.empty() ? catalog.name + "_catalog" : options.basename;
      const std::string spec_name = std::filesystem::path(options.spec).filename().string();
      const codegen::CppSources sources = codegen::cpp_catalog(catalog, basename, spec_name);
      if (!write_text((dir / (basename + ".hpp")).string(), sources.header) ||
          !write_text((dir / (basename + ".cpp")).string(), sources.source)) {
        return false;
      }
    } else if (format == "dot") {
      for (std::size_t i = 0; i < catalog.abstractions.size(); ++i) {
        if (!write_text(base + "." + catalog.abstractions[i].context + ".dot",
                        codegen::abstraction_dot(catalog, i))) {
          return false;
        }
      }
    }
  }
  return true;
}

int run_compile(const CompileOptions& options) {
  SourceManager sources;
  DiagnosticEngine diagnostics(sources, std::cerr, options.common.max_errors);
  auto loaded =
      load_model(options.spec, sources, diagnostics, effective_load_options(options.common));
  if (!loaded || diagnostics.has_errors()) return 1;
  if (!loaded->model) {
    std::cerr << options.spec
              << ": error: continuous models need the geometry layer, which this build does not "
                 "have yet\n";
    return 1;
  }
  codegen::BuildOptions build;
  build.p_correct = options.p_correct;
  std::string error;
  auto catalog = codegen::build_catalog(*loaded->model, codegen::spec_hash_of_file(options.spec),
                                        build, error);
  if (!catalog) {
    std::cerr << options.spec << ": error: " << error << '\n';
    return 1;
  }
  return emit(*catalog, options) ? 0 : 1;
}

}  // namespace

CommandRunner add_compile_command(CLI::App& app) {
  auto options = std::make_shared<CompileOptions>();
  CLI::App* command = app.add_subcommand(
      "compile", "Compile a spec into a catalog: the quotient and policy of every context");
  command->footer(
      "For every context: the coarsest bisimulation quotient (see 'oasisc quotient') and a\n"
      "policy solved on it by value iteration (docs/policies.md). Writes into DIR:\n"
      "  NAME.bin           the binary catalog the runtime loads (rt::LoadedCatalog)\n"
      "  NAME.json          the same for people and tools\n"
      "  NAME.CONTEXT.dot   each abstraction for Graphviz (bold: the policy's action)\n"
      "  NAME_catalog.hpp/.cpp  (--format cpp) C++ tables to link: NAME::catalog()\n"
      "Every file is written whole or not at all. --robust P adds what the runtime's robust\n"
      "filter needs: the full-state transitions of every context and a sensor that reports\n"
      "the true state with probability P.\n\n"
      "Examples:\n"
      "  oasisc compile specs/discrete_tracking.oasis -o out\n"
      "  oasisc verify specs/discrete_tracking.oasis out/discrete_tracking.bin");
  command->add_option("spec", options->spec, "Spec (.oasis) or model (.aut, .tra) file")
      ->required();
  command->add_option("-o,--output", options->output, "Output directory")->capture_default_str();
  command
      ->add_option("-f,--format", options->formats,
                   "Formats: bin, json, dot, cpp (default: bin,json,dot)")
      ->delimiter(',')
      ->check(CLI::IsMember({"bin", "json", "dot", "cpp"}));
  command->add_option("--basename", options->basename,
                      "File name (without extension) of the C++ output");
  command
      ->add_option("--robust", options->p_correct,
                   "Add the robust filter's section with this sensor accuracy")
      ->check(CLI::Range(0.0, 1.0));
  add_common_options(*command, options->common);
  return [options] { return run_compile(*options); };
}

}  // namespace oasis::cli
