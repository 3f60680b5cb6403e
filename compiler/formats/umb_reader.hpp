#pragma once
// Reader for UMB, the "unified Markov binary" format of PRISM 4.10 and Storm: a tar archive
// (plain, gzip or xz) holding `index.json` and little-endian binary arrays. docs/formats.md,
// "UMB", lists what is read:
//
//   index.json                               the counts, the probability type, annotations
//   state-to-choices.bin                     CSR: state -> its choices (absent: one each)
//   choice-to-branches.bin                   CSR: choice -> its branches (absent: one each)
//   branch-to-target.bin, -probability.bin   each branch's target and probability
//   state-is-initial.bin                     bitset of the initial states
//   actions/choices/{values,string-mapping,strings}.bin   the choices' action names
//   annotations/aps/ID/states/values.bin     bitset: an atomic proposition (a label)
//   annotations/rewards/ID/{states,choices,branches}/values.bin   a reward model
//   valuations/states/valuations.bin         the states' variables (umb_valuations.hpp)
//
// Numbers are exact: a rational is read as it is; a double as the shortest decimal that reads
// back as it (0.1, not 3602879701896397/2^55), as the text readers read what other tools print.
// Each reward annotation becomes one context (state and choice rewards; branch rewards must
// agree within their choice, as PRISM's transition rewards must); a file without one has the
// context "default". An MDP's choice is named by its action's string, an unlabelled one (the
// empty string, or no strings at all) by its place in its state, "[j]", as the other readers
// name them; a DTMC's one choice per state is the action "[0]". The initial states carry the
// label "init". Everything else of the file (other annotation groups, branch actions,
// metadata, valuations of a form the model does not hold) is read past.

#include <optional>

#include "formats/read_options.hpp"
#include "model/explicit_model.hpp"
#include "support/diagnostics.hpp"

namespace oasis::formats {

// Reads the UMB file `file` (already in the diagnostics' SourceManager, its bytes as they are
// on disk). A problem is reported as `PATH: error: ENTRY: message`; the result is nullopt if
// any error was reported.
std::optional<model::ExplicitModel> read_umb(FileId file, DiagnosticEngine& diagnostics,
                                             const ReadOptions& options);

}  // namespace oasis::formats
