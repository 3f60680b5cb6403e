#pragma once
// Reader for Storm's explicit DRN format ("direct encoding", .drn) of DTMCs and MDPs, as Storm's
// DirectEncodingExporter writes it and its DirectEncodingParser reads it. docs/formats.md,
// "Storm's DRN", gives what we accept:
//
//   // comments
//   @type: DTMC | MDP
//   @value_type: double | rational          (optional)
//   @parameters                             (the next line, empty: no parameters)
//   @reward_models                          (the next line: names separated by blanks)
//   @nr_states                              (the next line: N)
//   @nr_choices                             (optional; the next line: the number of choices)
//   @model
//   state S [R1, R2, ...] LABEL "LABEL WITH BLANKS" ...
//   	action NAME [R1, R2, ...]
//   		TARGET : PROBABILITY
//
// Values are read exactly (decimals, `1/3`). Each reward model becomes one context (state
// rewards and choice rewards), as a PRISM program's reward structures do; a file without
// reward models has the one context "default". An MDP's choices are named by their NAME, an
// unlabelled one (`__NOLABEL__`) by its place in its state, "[j]", as the .tra reader names
// them; a DTMC's one choice per state is the action "[0]". The states labelled "init" are
// the initial states.

#include <optional>

#include "formats/read_options.hpp"
#include "model/explicit_model.hpp"
#include "support/diagnostics.hpp"

namespace oasis::formats {

// Reads the DRN text of `file` (already in the diagnostics' SourceManager). Problems are
// reported at their line and column; the result is nullopt if any error was reported.
std::optional<model::ExplicitModel> read_drn(FileId file, DiagnosticEngine& diagnostics,
                                             const ReadOptions& options);

}  // namespace oasis::formats
