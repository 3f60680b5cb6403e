#include "formats/model_file.hpp"

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <system_error>

#include "formats/aut_reader.hpp"
#include "formats/drn_reader.hpp"
#include "formats/explicit_reader.hpp"
#include "formats/umb_reader.hpp"

namespace oasis::formats {
namespace {

std::optional<FileId> open_file(const std::string& path, SourceManager& sources,
                                DiagnosticEngine& diagnostics, const ReadOptions& options) {
  MappedFile file;
  std::string error;
  // Diagnostics locate bytes with 32-bit offsets; a larger file could not be reported on.
  if (!file.open(path, options.max_bytes, error)) {
    diagnostics.file_error(path, error);
    return std::nullopt;
  }
  return sources.add(path, std::move(file));
}

// A sibling that does not exist is simply absent; one that exists but cannot be read is
// an error (reported), which `failed` records.
std::optional<FileId> open_sibling(const std::filesystem::path& tra, const char* extension,
                                   SourceManager& sources, DiagnosticEngine& diagnostics,
                                   const ReadOptions& options, bool& failed) {
  std::filesystem::path sibling = tra;
  sibling.replace_extension(extension);
  std::error_code code;
  if (!std::filesystem::exists(sibling, code)) return std::nullopt;
  std::optional<FileId> file = open_file(sibling.string(), sources, diagnostics, options);
  if (!file) failed = true;
  return file;
}

std::optional<model::ExplicitModel> read_prism_file(const std::string& path, SourceManager& sources,
                                                    DiagnosticEngine& diagnostics,
                                                    const ReadOptions& options) {
  const std::optional<FileId> transitions = open_file(path, sources, diagnostics, options);
  if (!transitions) return std::nullopt;
  PrismFiles files;
  files.transitions = *transitions;
  bool failed = false;
  files.states = open_sibling(path, ".sta", sources, diagnostics, options, failed);
  files.labels = open_sibling(path, ".lab", sources, diagnostics, options, failed);
  files.state_rewards = open_sibling(path, ".srew", sources, diagnostics, options, failed);
  files.transition_rewards = open_sibling(path, ".trew", sources, diagnostics, options, failed);
  if (failed) return std::nullopt;
  return read_prism(files, diagnostics, options);
}

}  // namespace

std::optional<model::ExplicitModel> read_model_file(const std::string& path, SourceManager& sources,
                                                    DiagnosticEngine& diagnostics,
                                                    const ReadOptions& options) {
  const std::string extension = std::filesystem::path(path).extension().string();
  if (extension == ".aut") {
    const std::optional<FileId> file = open_file(path, sources, diagnostics, options);
    if (!file) return std::nullopt;
    return read_aut(*file, diagnostics, options);
  }
  if (extension == ".drn") {
    const std::optional<FileId> file = open_file(path, sources, diagnostics, options);
    if (!file) return std::nullopt;
    return read_drn(*file, diagnostics, options);
  }
  if (extension == ".umb") {
    const std::optional<FileId> file = open_file(path, sources, diagnostics, options);
    if (!file) return std::nullopt;
    return read_umb(*file, diagnostics, options);
  }
  if (extension == ".tra") return read_prism_file(path, sources, diagnostics, options);
  diagnostics.file_error(path, "unknown model file type '" + extension +
                                   "': expected .aut (mCRL2), .tra (PRISM or Storm explicit), "
                                   ".drn (Storm) or .umb (PRISM and Storm's binary format)");
  return std::nullopt;
}

}  // namespace oasis::formats
