#include "codegen/catalog_files.hpp"

#include <algorithm>
#include <filesystem>

#include "codegen/abstraction_svg.hpp"
#include "codegen/binary_catalog.hpp"
#include "codegen/continuous_json.hpp"
#include "codegen/cpp_catalog.hpp"
#include "codegen/dot_catalog.hpp"
#include "codegen/json_catalog.hpp"
#include "codegen/json_writer.hpp"
#include "oasis/rt/catalog_sections.hpp"
#include "oasis/rt/spec_hash.hpp"
#include "pipeline/continuous_catalog_data.hpp"

namespace oasis::codegen {

namespace fs = std::filesystem;

bool wants(const CatalogFileOptions& options, const char* format) {
  return std::find(options.formats.begin(), options.formats.end(), format) != options.formats.end();
}

std::vector<std::string> default_catalog_formats(bool continuous) {
  return continuous ? std::vector<std::string>{"bin", "json", "svg"}
                    : std::vector<std::string>{"bin", "json", "dot"};
}

const char* unfitting_drawing(const CatalogFileOptions& options, bool continuous) {
  if (continuous) return wants(options, "dot") ? "dot" : nullptr;
  return wants(options, "svg") ? "svg" : nullptr;
}

// Why `-o -` cannot take this compile's files, or "" when they are one file: standard output
// holds one file, and a second one would follow half a catalog already written.
std::string one_file_error(const CatalogFileOptions& options, std::size_t contexts) {
  if (options.formats.size() != 1) {
    return "-o - writes one file to standard output: choose one --format (bin, json, or dot or "
           "svg for a single context)";
  }
  if (wants(options, "cpp")) return "-o - cannot take --format cpp, which writes two files";
  if ((wants(options, "dot") || wants(options, "svg")) && contexts != 1) {
    return "-o - writes one file to standard output, and --format " + options.formats.front() +
           " writes one per context (" + std::to_string(contexts) + " here)";
  }
  return "";
}

namespace {

// The binary file from `data`; the C++ tables from `linked`, which is `data` for discrete
// catalogs and the catalog without its transition rows for continuous ones (a robot links
// the partition, rewards and policies, not the analysis product).
bool write_common(const CatalogFileOptions& options, const model::CatalogData& data,
                  const model::CatalogData& linked, OutputSet& out, std::string& error) {
  if (wants(options, "bin")) {
    const std::string bytes = binary_catalog(data);
    // Never write a catalog the runtime's loader would refuse.
    if (bytes.size() > rt::kMaxCatalogFileBytes) {
      error = "the binary catalog would be " + std::to_string(bytes.size()) +
              " bytes, more than the runtime loads (" + std::to_string(rt::kMaxCatalogFileBytes) +
              "); compile without --with-transitions or with a coarser --epsilon";
      return false;
    }
    if (!out.write(data.name + ".bin", bytes, error)) return false;
  }
  if (!wants(options, "cpp")) return true;
  const std::string basename =
      options.basename.empty() ? linked.name + "_catalog" : options.basename;
  const std::string spec_name = fs::path(options.spec).filename().string();
  const CppSources sources = cpp_catalog(linked, basename, spec_name);
  return out.write(basename + ".hpp", sources.header, error) &&
         out.write(basename + ".cpp", sources.source, error);
}

}  // namespace

bool write_discrete_catalog(const CatalogFileOptions& options, model::CatalogData& data,
                            OutputSet& out, std::string& error) {
  if (out.to_standard_output() &&
      !(error = one_file_error(options, data.abstractions.size())).empty())
    return false;
  if (!write_common(options, data, data, out, error)) return false;
  if (wants(options, "json") &&
      !out.write(data.name + ".json", catalog_json(data).dump(2) + "\n", error))
    return false;
  for (std::size_t i = 0; wants(options, "dot") && i < data.abstractions.size(); ++i) {
    if (!out.write(data.name + "." + data.abstractions[i].context + ".dot",
                   abstraction_dot(data, i), error))
      return false;
  }
  return true;
}

bool write_continuous_catalog(const CatalogFileOptions& options,
                              const pipeline::ContinuousCatalog& catalog, OutputSet& out,
                              std::string& error) {
  if (out.to_standard_output() &&
      !(error = one_file_error(options, catalog.abstractions.size())).empty())
    return false;
  model::CatalogData data = pipeline::continuous_catalog_data(catalog, options.with_transitions);
  model::CatalogData linked = options.with_transitions && wants(options, "cpp")
                                  ? pipeline::continuous_catalog_data(catalog, false)
                                  : model::CatalogData{};
  if (!write_common(options, data, options.with_transitions ? linked : data, out, error))
    return false;
  const auto stream_json = [&](AtomicFile& file) {
    JsonWriter writer([&file](std::string_view piece) { file.append(piece); });
    write_continuous_catalog_json(writer, catalog, options.with_transitions);
    writer.finish();
  };
  if (wants(options, "json") && !out.write_with(catalog.name + ".json", stream_json, error))
    return false;
  for (std::size_t i = 0; wants(options, "svg") && i < catalog.abstractions.size(); ++i) {
    if (!out.write(catalog.name + "." + catalog.abstractions[i].context + ".svg",
                   abstraction_svg(catalog, i), error))
      return false;
  }
  return true;
}

// What goes in the marker file: enough to tell which spec and options made the set, and
// nothing that changes between identical runs.
std::string marker_text(const CatalogFileOptions& options, std::uint64_t hash,
                        const OutputSet& out) {
  std::string text = "written by oasisc " + std::string(OASIS_VERSION) + " compile\n";
  text += "spec " + fs::path(options.spec).filename().string() + " " + rt::spec_hash_text(hash) +
          "\nfiles";
  for (const std::string& name : out.names())
    text += " " + name;
  return text + "\n";
}

}  // namespace oasis::codegen
