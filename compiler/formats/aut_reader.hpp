#pragma once
// Reader for mCRL2's probabilistic Aldebaran (.aut) files. docs/formats.md gives the grammar
// we accept and the encoding of rewards in labels (see also aut_label.hpp).

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

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

// --- Reading one part of a file, for a distributed reader ---------------------------------
// The body of the file (the lines after the header) is cut into `count` parts of nearly equal
// bytes, each moved forward to the start of a line; part `index` is the lines that start in
// it. Every line is checked as read_aut checks it and handed to the sink, one distribution
// at a time, normalized (targets ascending and distinct). Nothing is collected: the sink
// decides where the line goes.

struct AutLine {
  SourceOffset offset = 0;  // of the label, for diagnostics
  model::StateIndex source = 0;
  model::ActionIndex action = 0;         // into AutPart::actions
  ValueId reward = RationalPool::kZero;  // into AutPart::values
  std::span<const std::pair<model::StateIndex, ValueId>> row;
};

// What a part's reader learnt besides its lines: the header, the part's actions and values
// (numbered in order of first appearance within the part) and how many lines it read.
struct AutPart {
  std::uint32_t num_states = 0;
  std::vector<model::StateIndex> initial;
  std::uint64_t declared_transitions = 0;
  SourceOffset declared_transitions_offset = 0;  // where the header gives that number
  std::uint64_t lines = 0;
  std::vector<std::string> actions;
  // Where each action first appears in the part: the whole file's order of first appearance
  // (read_aut's action numbering) is the order of the smallest over all parts.
  std::vector<SourceOffset> action_offsets;
  RationalPool values;
};

using AutLineSink = std::function<void(const AutLine&)>;

// nullopt if any error was reported. The count of lines is not checked against the header
// (only the sum over all parts can be): the caller does that. `header_read` tells whether
// the errors, if any, are in the part (every part's reader reads the header, so a distributed
// caller reports header errors once).
std::optional<AutPart> read_aut_part(FileId file, DiagnosticEngine& diagnostics,
                                     const ReadOptions& options, std::uint32_t index,
                                     std::uint32_t count, const AutLineSink& sink,
                                     bool& header_read);

}  // namespace oasis::formats
