#pragma once
// Reader for PRISM's explicit model files of an MDP: the transitions (.tra) and, when they
// exist beside it with the same stem, states (.sta), labels (.lab), state rewards (.srew) and
// transition rewards (.trew). docs/formats.md gives the grammar we accept.

#include <optional>
#include <string>

#include "formats/read_options.hpp"
#include "model/explicit_model.hpp"
#include "support/diagnostics.hpp"

namespace oasis::formats {

// The files of one model, already in the diagnostics' SourceManager.
struct PrismFiles {
  FileId transitions = 0;
  std::optional<FileId> states;
  std::optional<FileId> labels;
  std::optional<FileId> state_rewards;
  std::optional<FileId> transition_rewards;
};

// The model has one context, "default". Actions are the .tra action labels in order of
// first appearance; an unlabelled choice with index j of its state is the action "[j]".
// .sta gives the variables and valuations; the "init" label of .lab the initial states
// (state 0 without a .lab); .srew the state rewards; .trew the choice rewards. Problems are
// reported through `diagnostics`; nullopt if any error was reported.
std::optional<model::ExplicitModel> read_prism(const PrismFiles& files,
                                               DiagnosticEngine& diagnostics,
                                               const ReadOptions& options);

// The name an unlabelled choice with index `choice` gets: "[choice]".
std::string unlabelled_action_name(std::uint32_t choice);

}  // namespace oasis::formats
