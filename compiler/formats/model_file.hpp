#pragma once
// Reading a model file by name: the extension picks the format.

#include <optional>
#include <string>

#include "formats/read_options.hpp"
#include "model/explicit_model.hpp"
#include "support/diagnostics.hpp"
#include "support/source_manager.hpp"

namespace oasis::formats {

// Reads `path` (.aut: mCRL2; .drn: Storm's DRN; .umb: UMB; .tra: PRISM or Storm, with its
// .sta/.lab/.srew/.trew siblings when they exist). Files are memory-mapped and registered in
// `sources`; a file that cannot be opened, or an unknown extension, is reported with
// diagnostics.file_error().
std::optional<model::ExplicitModel> read_model_file(const std::string& path, SourceManager& sources,
                                                    DiagnosticEngine& diagnostics,
                                                    const ReadOptions& options);

}  // namespace oasis::formats
