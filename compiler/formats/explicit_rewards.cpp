// Reward files, each optionally preceded by PRISM's '# Reward structure' comments:
//
//   .srew  STATES NONZERO            then  STATE REWARD
//   .trew  STATES CHOICES NONZERO    then  STATE CHOICE TARGET REWARD
//          STATES NONZERO            then  STATE TARGET REWARD          (a Markov chain)
//
// An MDP transition reward belongs to the choice: PRISM repeats it on every target row of
// the choice, and so must the file (rows of one choice that disagree are an error). A Markov
// chain's state has one choice, so its rows must agree the same way.

#include <algorithm>

#include "formats/explicit_parts.hpp"

namespace oasis::formats {
namespace {

// Reads the header's numbers; checks the first against the model's state count.
bool read_header(PrismScanner& scan, int count, std::uint32_t num_states, const char* shape,
                 std::uint64_t& declared_rows, const char*& header) {
  if (!scan.next_line()) {
    scan.error_here(std::string("empty rewards file: expected the header '") + shape + "'");
    return false;
  }
  header = scan.position();
  std::uint64_t numbers[3] = {};
  for (int i = 0; i < count; ++i) {
    scan.skip_blanks();
    const Natural number = scan.read_natural();
    if (number.empty()) {
      scan.error_here(std::string("expected the header '") + shape + "'");
      return false;
    }
    numbers[i] = number.overflow ? UINT64_MAX : number.value;
  }
  if (!scan.expect_line_end("the header")) return false;
  if (numbers[0] != num_states) {
    scan.error_at(header, 1,
                  "the header declares " + std::to_string(numbers[0]) +
                      " states but the transitions file has " + std::to_string(num_states));
    return false;
  }
  declared_rows = numbers[count - 1];
  scan.skip_line();
  return true;
}

std::optional<ValueId> read_reward(PrismScanner& scan, ValueCache& values) {
  scan.skip_blanks();
  const char* token = scan.position();
  const std::string_view text = scan.read_word();
  const std::optional<ValueId> id = text.empty() ? std::nullopt : values.intern_text(text);
  if (!id) {
    scan.error_at(token, text.size(), "reward '" + std::string(text) + "' is not a number");
    return id;
  }
  if (!values.check_carried(*id, "reward", scan.range_at(token, text.size()), scan.diagnostics()))
    return std::nullopt;
  return id;
}

void check_rows(PrismScanner& scan, const char* header, std::uint64_t declared,
                std::uint64_t rows) {
  if (declared == rows || scan.diagnostics().should_stop()) return;
  scan.error_at(header, 1,
                "the header declares " + std::to_string(declared) + " rewards but the file has " +
                    std::to_string(rows));
}

}  // namespace

bool read_prism_state_rewards(FileId file, DiagnosticEngine& diagnostics, std::uint32_t num_states,
                              ValueCache& values, std::vector<ValueId>& rewards) {
  PrismScanner scan(file, diagnostics);
  const std::size_t errors = diagnostics.error_count();
  std::uint64_t declared = 0;
  const char* header = nullptr;
  if (!read_header(scan, 2, num_states, "states rewards", declared, header)) return false;
  std::vector<bool> given(num_states, false);
  std::uint64_t rows = 0;
  for (; scan.next_line() && !diagnostics.should_stop(); scan.skip_line()) {
    const char* token = scan.position();
    model::StateIndex state = 0;
    if (!scan.read_state(num_states, "a state index", state)) continue;
    const std::optional<ValueId> reward = read_reward(scan, values);
    if (!reward || !scan.expect_line_end("the reward")) continue;
    ++rows;
    if (given[state]) {
      scan.error_at(token, 1, "state " + std::to_string(state) + " has a second reward");
      continue;
    }
    given[state] = true;
    rewards[state] = *reward;
  }
  check_rows(scan, header, declared, rows);
  return diagnostics.error_count() == errors;
}

ChoiceTable::ChoiceTable(const PrismTransitions& transitions)
    : state_begin_(std::size_t{transitions.num_states} + 1, 0) {
  const DistributionCollector& collector = transitions.collector;
  for (std::uint32_t d = 0; d < collector.size(); ++d)
    ++state_begin_[collector.source(d) + 1];
  for (std::size_t s = 0; s + 1 < state_begin_.size(); ++s)
    state_begin_[s + 1] += state_begin_[s];
  choices_.resize(collector.size());
  std::vector<std::uint32_t> cursor(state_begin_.begin(), state_begin_.end() - 1);
  for (std::uint32_t d = 0; d < collector.size(); ++d) {
    choices_[cursor[collector.source(d)]++] = {collector.payload(d), collector.action(d)};
  }
}

std::optional<model::ActionIndex> ChoiceTable::action(model::StateIndex state,
                                                      std::uint32_t choice) const {
  const auto begin = choices_.begin() + state_begin_[state];
  const auto end = choices_.begin() + state_begin_[state + 1];
  const auto found = std::find_if(begin, end, [&](const auto& c) { return c.first == choice; });
  if (found == end) return std::nullopt;
  return found->second;
}

bool read_prism_transition_rewards(FileId file, DiagnosticEngine& diagnostics,
                                   std::uint32_t num_states, std::uint32_t num_actions,
                                   const ChoiceTable& choices, bool markov_chain,
                                   ValueCache& values, std::vector<ValueId>& rewards) {
  PrismScanner scan(file, diagnostics);
  const std::size_t errors = diagnostics.error_count();
  std::uint64_t declared = 0;
  const char* header = nullptr;
  if (!read_header(scan, markov_chain ? 2 : 3, num_states,
                   markov_chain ? "states rewards" : "states choices rewards", declared, header))
    return false;
  std::vector<bool> given(rewards.size(), false);
  std::uint64_t rows = 0;
  for (; scan.next_line() && !diagnostics.should_stop(); scan.skip_line()) {
    const char* row = scan.position();
    model::StateIndex state = 0;
    model::StateIndex target = 0;
    std::uint32_t choice = 0;
    if (!scan.read_state(num_states, "a state index", state)) continue;
    scan.skip_blanks();
    if (!markov_chain && !scan.read_index("the choice index", choice)) continue;
    scan.skip_blanks();
    if (!scan.read_state(num_states, "the target state", target)) continue;
    const std::optional<ValueId> reward = read_reward(scan, values);
    if (!reward || !scan.expect_line_end("the reward")) continue;
    ++rows;
    const std::optional<model::ActionIndex> action = choices.action(state, choice);
    if (!action) {
      scan.error_at(row, 1,
                    "state " + std::to_string(state) + " has no choice " + std::to_string(choice) +
                        " in the transitions file");
      continue;
    }
    const std::size_t c = std::size_t{state} * num_actions + *action;
    if (given[c] && rewards[c] != *reward) {
      scan.error_at(row, 1,
                    "rows of state " + std::to_string(state) + ", choice " +
                        std::to_string(choice) + " give different rewards");
      continue;
    }
    given[c] = true;
    rewards[c] = *reward;
  }
  check_rows(scan, header, declared, rows);
  return diagnostics.error_count() == errors;
}

}  // namespace oasis::formats
