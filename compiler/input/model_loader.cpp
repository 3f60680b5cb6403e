#include "input/model_loader.hpp"

#include <algorithm>
#include <cstdio>
#include <iostream>

#include "formats/model_file.hpp"
#include "frontend/load_spec.hpp"
#include "model/explorer.hpp"
#include "oasis/rt/spec_hash.hpp"
#include "policy/solvability.hpp"
#include "prism/imported_catalog.hpp"
#include "prism/load_program.hpp"
#include "property/catalog_guarantees.hpp"

namespace oasis::input {
namespace {

// rt::spec_hash of a file's text, in steps that hand the pages read back to the kernel, so
// that hashing a large model file does not make it resident again after its reader let it go.
std::uint64_t hash_text(const SourceFile& file) {
  constexpr std::size_t kStep = std::size_t{16} << 20;
  const std::string_view text = file.text();
  std::uint64_t hash = rt::kFnv1a64Basis;
  for (std::size_t done = 0; done < text.size(); done += kStep) {
    const std::size_t size = std::min(kStep, text.size() - done);
    hash = rt::fnv1a64(reinterpret_cast<const unsigned char*>(text.data() + done), size, hash);
    file.release_pages_before(done + size);
  }
  return hash;
}

void print_progress(std::uint64_t found, std::uint64_t explored) {
  std::cerr << "\rexploring: " << explored << " of " << found << " states found so far"
            << std::flush;
}

prism::LoadOptions prism_load_options(const LoadOptions& options) {
  prism::LoadOptions prism_options;
  prism_options.constants = options.constants;
  // The option's check has parsed it already (common_options.cpp).
  prism_options.rewards =
      model::LabelSelection::parse(options.rewards).value_or(model::LabelSelection{});
  prism_options.max_bytes = options.max_spec_bytes;
  prism_options.max_number_bits = options.max_number_bits;
  prism_options.explore.max_states = options.max_states;
  if (options.progress) {
    prism_options.explore.progress = print_progress;
  } else {
    prism_options.explore.progress = options.on_progress;
  }
  return prism_options;
}

std::optional<model::ExplicitModel> load_prism_program(const std::string& path,
                                                       SourceManager& sources,
                                                       DiagnosticEngine& diagnostics,
                                                       const LoadOptions& options,
                                                       LoadedModel& loaded) {
  prism::LoadOptions prism_options = prism_load_options(options);
  prism_options.names = &loaded.names;
  auto model = prism::load_program(path, sources, diagnostics, prism_options);
  if (options.progress) std::cerr << "\r\033[K" << std::flush;
  return model;
}

// The model's stated properties, parsed into `loaded` (errors placed in the spec).
bool parse_properties(LoadedModel& loaded, DiagnosticEngine& diagnostics) {
  auto properties = property::parse_stated_properties(
      loaded.model ? loaded.model->properties : loaded.ir->properties, diagnostics);
  if (!properties) return false;
  loaded.properties = std::move(*properties);
  return true;
}

// A spec that imports a PRISM program: the program explored, with the spec's catalog. The
// hash covers the spec's bytes followed by the program's, so that a catalog compiled from them
// is stale when either changes.
bool load_imported_program(LoadedModel& loaded, FileId spec_file, SourceManager& sources,
                           DiagnosticEngine& diagnostics, const LoadOptions& options) {
  const FileId program_file = sources.num_files();
  prism::LoadOptions prism_options = prism_load_options(options);
  prism_options.names = &loaded.names;
  loaded.model =
      prism::load_imported_catalog(*loaded.ir, loaded.path, sources, diagnostics, prism_options);
  if (options.progress) std::cerr << "\r\033[K" << std::flush;
  if (!loaded.model) return false;
  std::string both(sources.file(spec_file).text());
  both += sources.file(program_file).text();
  loaded.source_hash = rt::spec_hash(both);
  if (const auto reason = policy::unsolvable_reason(*loaded.model)) {
    diagnostics.error(loaded.ir->objective_range, *reason);
    return false;
  }
  loaded.ir.reset();  // what the spec says is in the model now
  loaded.prism_program = true;
  return parse_properties(loaded, diagnostics);
}

}  // namespace

std::optional<LoadedModel> load_model(const std::string& path, SourceManager& sources,
                                      DiagnosticEngine& diagnostics, const LoadOptions& options) {
  LoadedModel loaded;
  loaded.path = path;
  // The input is the first file the front end or the reader adds; hash the bytes it parsed.
  const FileId input = sources.num_files();
  const auto hash_input = [&] {
    if (options.hash_source) loaded.source_hash = hash_text(sources.file(input));
  };
  if (prism::is_program_path(path)) {
    loaded.prism_program = true;
    loaded.model = load_prism_program(path, sources, diagnostics, options, loaded);
    if (!loaded.model) return std::nullopt;
    hash_input();
    return loaded;
  }
  if (path.ends_with(".aut") || path.ends_with(".tra") || path.ends_with(".drn") ||
      path.ends_with(".umb")) {
    formats::ReadOptions read_options;
    read_options.max_bytes = options.max_input_bytes;
    read_options.max_number_bits = options.max_number_bits;
    read_options.max_states = options.max_states;
    read_options.memory_budget = options.memory_budget;
    loaded.model = formats::read_model_file(path, sources, diagnostics, read_options);
    if (!loaded.model) return std::nullopt;
    hash_input();
    if (const auto reason = policy::unsolvable_reason(*loaded.model)) {
      diagnostics.file_error(path, *reason);
      return std::nullopt;
    }
    return loaded;
  }
  loaded.ir = frontend::load_spec(
      path, sources, diagnostics,
      {.max_bytes = options.max_spec_bytes, .max_number_bits = options.max_number_bits});
  if (!loaded.ir) return std::nullopt;
  hash_input();
  if (loaded.ir->imported) {
    if (!load_imported_program(loaded, input, sources, diagnostics, options)) return std::nullopt;
    return loaded;
  }
  if (!options.explore || loaded.ir->kind == model::ModelKind::Continuous) {
    if (!parse_properties(loaded, diagnostics)) return std::nullopt;
    return loaded;
  }

  model::ExploreOptions explore_options{.max_states = options.max_states,
                                        .progress = options.on_progress};
  if (options.progress) explore_options.progress = print_progress;
  loaded.model = model::explore(*loaded.ir, diagnostics, explore_options);
  if (options.progress) std::cerr << "\r\033[K" << std::flush;
  if (!loaded.model) return std::nullopt;
  // What `compile` would meet when solving the policies is an error of the spec, here.
  if (const auto reason = policy::unsolvable_reason(*loaded.model)) {
    diagnostics.error(loaded.ir->objective_range, *reason);
    return std::nullopt;
  }
  if (!parse_properties(loaded, diagnostics)) return std::nullopt;
  return loaded;
}

}  // namespace oasis::input
