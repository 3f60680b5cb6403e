#pragma once
// The files of a compiled catalog, written as `oasisc compile` (and `oasisc-mpi compile`)
// write them: the binary catalog, its JSON, a DOT or SVG drawing per context, the C++ tables,
// each through an AtomicFile into the output set, and the marker that names them.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <set>
#include <string>
#include <vector>

#include "files/output_names.hpp"
#include "model/catalog_data.hpp"
#include "pipeline/continuous_catalog.hpp"
#include "support/atomic_file.hpp"

namespace oasis::codegen {

// What the writers need of a compile's options.
struct CatalogFileOptions {
  std::string spec;                  // the spec's path: its name goes in the C++ and the marker
  std::vector<std::string> formats;  // bin, json, dot, svg, cpp
  std::string basename;              // of the C++ files; default NAME_catalog
  bool with_transitions = false;     // continuous: also the quotient's transition rows
};

bool wants(const CatalogFileOptions& options, const char* format);

// The formats a catalog compile writes when none are asked for: bin, json and the drawing that
// fits the model (dot for explicit quotients, svg for continuous abstractions).
std::vector<std::string> default_catalog_formats(bool continuous);
// The drawing asked for that does not fit the model ("svg" for a discrete one, "dot" for a
// continuous one), or nullptr.
const char* unfitting_drawing(const CatalogFileOptions& options, bool continuous);

// The files of one compile, written into the staging directory, named relative to it, or
// the one file of a compile to standard output (an empty directory).
class OutputSet {
 public:
  explicit OutputSet(std::string directory) : directory_(std::move(directory)) {}

  [[nodiscard]] bool to_standard_output() const { return directory_.empty(); }

  bool write(const std::string& name, const std::string& bytes, std::string& error) {
    return write_with(
        name, [&bytes](AtomicFile& file) { file.append(bytes); }, error);
  }
  // `fill` appends the file's text piece by piece (large files never exist whole in memory).
  bool write_with(const std::string& name, const std::function<void(AtomicFile&)>& fill,
                  std::string& error) {
    if (to_standard_output() && !names_.empty()) {
      // Checked before anything is written (one_file_error), so this is a bug guard.
      error = "-o - writes one file, and this compile makes more than " + *names_.begin();
      return false;
    }
    // Names come from the model and its contexts (a PRISM reward structure may be called
    // "a/../../x"): each must name a file in the folder, and only once.
    if (const std::string problem = files::plain_file_name_problem(name); !problem.empty()) {
      error = "a file of the catalog would be named " + problem;
      return false;
    }
    if (names_.count(name) != 0) {
      error = "two files of the catalog would be named \"" + text::printable_excerpt(name) + "\"";
      return false;
    }
    AtomicFile file;
    if (!file.open(to_standard_output() ? "-" : (std::filesystem::path(directory_) / name).string(),
                   error))
      return false;
    fill(file);
    if (!file.commit(error)) return false;
    names_.insert(name);
    return true;
  }
  [[nodiscard]] const std::set<std::string>& names() const { return names_; }

 private:
  std::string directory_;
  std::set<std::string> names_;
};

// Why `-o -` cannot take this compile's files, or "" when they are one file: standard output
// holds one file, and a second one would follow half a catalog already written.
std::string one_file_error(const CatalogFileOptions& options, std::size_t contexts);

bool write_discrete_catalog(const CatalogFileOptions& options, model::CatalogData& data,
                            OutputSet& out, std::string& error);
bool write_continuous_catalog(const CatalogFileOptions& options,
                              const pipeline::ContinuousCatalog& catalog, OutputSet& out,
                              std::string& error);

// What goes in the marker file: enough to tell which spec and options made the set, and
// nothing that changes between identical runs.
std::string marker_text(const CatalogFileOptions& options, std::uint64_t hash,
                        const OutputSet& out);

}  // namespace oasis::codegen
