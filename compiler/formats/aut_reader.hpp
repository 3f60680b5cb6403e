#pragma once
// Reader for mCRL2's probabilistic Aldebaran (.aut) files. docs/formats.md gives the grammar
// we accept and the encoding of rewards in labels (see also aut_label.hpp).

#include <optional>

#include "formats/read_options.hpp"
#include "model/explicit_model.hpp"
#include "support/diagnostics.hpp"

namespace oasis::formats {

// Reads the .aut text of `file` (already in the diagnostics' SourceManager). The model has
// one context, "default"; states are the file's indices (no names); actions are numbered in
// order of first appearance; rewards decoded from the labels are choice rewards (state
// rewards all zero; `rewards.choice` stays empty when every reward is zero). Problems are
// reported through `diagnostics`; the result is nullopt if any error was reported.
std::optional<model::ExplicitModel> read_aut(FileId file, DiagnosticEngine& diagnostics,
                                             const ReadOptions& options);

}  // namespace oasis::formats
