#pragma once
// The pieces read_prism() is made of, one file format each (explicit_transitions.cpp,
// explicit_states.cpp, explicit_labels.cpp, explicit_rewards.cpp), and the line handling they
// share. Internal to the formats layer.

#include <cstdint>
#include <string>
#include <vector>

#include "formats/distribution_collector.hpp"
#include "formats/read_options.hpp"
#include "formats/text_scanner.hpp"
#include "formats/value_cache.hpp"
#include "model/explicit_model.hpp"
#include "support/diagnostics.hpp"

namespace oasis::formats {

// A scanner over one PRISM file that reports errors at text positions of that file.
class PrismScanner : public TextScanner {
 public:
  PrismScanner(FileId file, DiagnosticEngine& diagnostics)
      : TextScanner(diagnostics.sources().file(file).text()),
        file_(file),
        diagnostics_(diagnostics) {}

  // Skips blank lines and comment lines ('#' first); false at the end of the file.
  bool next_line() {
    for (;;) {
      skip_blank_lines();
      skip_blanks();
      if (at_end()) return false;
      if (peek() != '#') return true;
      skip_line();
    }
  }
  [[nodiscard]] SourceRange range_at(const char* position, std::size_t length) const {
    return SourceRange{location(position), static_cast<std::uint32_t>(length == 0 ? 1 : length)};
  }
  void error_at(const char* position, std::size_t length, const std::string& message) {
    diagnostics_.error(range_at(position, length), message);
  }
  void error_here(const std::string& message) { error_at(position(), 1, message); }
  [[nodiscard]] SourceLocation location(const char* position) const {
    return {file_, offset_of(position)};
  }
  [[nodiscard]] std::uint64_t line_of(SourceOffset offset) const {
    return diagnostics_.sources().file(file_).line_column(offset).line;
  }
  [[nodiscard]] FileId file() const { return file_; }
  [[nodiscard]] const std::string& path() const {
    return diagnostics_.sources().file(file_).path();
  }
  [[nodiscard]] DiagnosticEngine& diagnostics() { return diagnostics_; }

  // A state index below `num_states`, or an error at it; `what` names it in messages.
  bool read_state(std::uint32_t num_states, const char* what, model::StateIndex& state);
  // Any natural that fits 32 bits.
  bool read_index(const char* what, std::uint32_t& index);
  // Blanks, then the end of the line, or an error.
  bool expect_line_end(const char* after);
  bool expect(char c, const std::string& message);

 private:
  FileId file_;
  DiagnosticEngine& diagnostics_;
};

// What the .tra file says. Distribution payloads are the choice indices j.
struct PrismTransitions {
  // A Markov chain's file (header 'states transitions', rows without a choice column): read
  // as an MDP with one action, unlabelled_action_name(0), and one choice per state.
  bool markov_chain = false;
  std::uint32_t num_states = 0;
  std::vector<std::string> actions;
  DistributionCollector collector;
  std::vector<model::StateIndex> initial;  // from "- - s -" lines, if any
  bool has_initial_lines = false;
};

bool read_prism_transitions(FileId file, DiagnosticEngine& diagnostics, const ReadOptions& options,
                            ValueCache& values, PrismTransitions& transitions);

// Variables and valuations; every state must be listed once.
bool read_prism_states(FileId file, DiagnosticEngine& diagnostics, model::StateSpace& states);

// Every label of a .lab file, and the states carrying "init"; `found` tells whether the file
// has that label.
bool read_prism_labels(FileId file, DiagnosticEngine& diagnostics, std::uint32_t num_states,
                       std::vector<model::StateIndex>& initial, model::StateLabels& labels,
                       bool& found);

bool read_prism_state_rewards(FileId file, DiagnosticEngine& diagnostics, std::uint32_t num_states,
                              ValueCache& values, std::vector<ValueId>& rewards);

// (state, choice index) -> action, for transition rewards, which name choices by index.
class ChoiceTable {
 public:
  ChoiceTable(const PrismTransitions& transitions);
  // The action of choice `choice` of `state`, or nullopt if the .tra file has no such choice.
  [[nodiscard]] std::optional<model::ActionIndex> action(model::StateIndex state,
                                                         std::uint32_t choice) const;

 private:
  std::vector<std::uint32_t> state_begin_;
  std::vector<std::pair<std::uint32_t, model::ActionIndex>> choices_;
};

// `markov_chain`: the Markov chain form, header 'states rewards' and rows 'state target
// reward' (the one choice, 0, implied).
bool read_prism_transition_rewards(FileId file, DiagnosticEngine& diagnostics,
                                   std::uint32_t num_states, std::uint32_t num_actions,
                                   const ChoiceTable& choices, bool markov_chain,
                                   ValueCache& values, std::vector<ValueId>& rewards);

}  // namespace oasis::formats
