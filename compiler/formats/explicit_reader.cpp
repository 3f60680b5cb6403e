#include "formats/explicit_reader.hpp"

#include <algorithm>
#include <filesystem>

#include "formats/explicit_parts.hpp"

namespace oasis::formats {
namespace {

using model::StateIndex;

void report_duplicate(DiagnosticEngine& diagnostics, FileId file, const PrismTransitions& tra,
                      const DistributionCollector::Duplicate& duplicate) {
  const DistributionCollector& choices = tra.collector;
  const StateIndex state = choices.source(duplicate.first);
  const std::uint32_t first_choice = choices.payload(duplicate.first);
  const std::uint32_t second_choice = choices.payload(duplicate.second);
  const SourceLocation first{file, choices.offset(duplicate.first)};
  const SourceLocation second{file, choices.offset(duplicate.second)};
  const std::string choice =
      "state " + std::to_string(state) + ", choice " + std::to_string(first_choice);
  if (first_choice == second_choice) {
    diagnostics.error(second,
                      "more rows of " + choice +
                          " after rows of other choices; the rows of a choice must be adjacent");
    diagnostics.note(first, "the rows of " + choice + " start here");
    return;
  }
  const std::string& action = tra.actions[choices.action(duplicate.first)];
  const std::uint32_t first_line = diagnostics.sources().file(file).line_column(first.offset).line;
  diagnostics.error(
      second, "state " + std::to_string(state) + " has two choices with action '" + action +
                  "' (choices " + std::to_string(first_choice) + " and " +
                  std::to_string(second_choice) + ", lines " + std::to_string(first_line) +
                  " and " +
                  std::to_string(diagnostics.sources().file(file).line_column(second.offset).line) +
                  "); an MDP allows one per action");
  diagnostics.note(first, "choice " + std::to_string(first_choice) + " of state " +
                              std::to_string(state) + " is here");
}

// The transition matrix, or nullopt with every repeated (state, action) reported.
std::optional<model::TransitionMatrix> build_matrix(const PrismFiles& files,
                                                    DiagnosticEngine& diagnostics,
                                                    PrismTransitions& tra, RationalPool& values) {
  const auto k = static_cast<std::uint32_t>(tra.actions.size());
  if (std::uint64_t{tra.num_states} * k >= UINT32_MAX) {
    diagnostics.error(SourceLocation{files.transitions, 0},
                      std::to_string(tra.num_states) + " states and " + std::to_string(k) +
                          " actions make more than 2^32 state-action pairs");
    return std::nullopt;
  }
  std::vector<DistributionCollector::Duplicate> duplicates;
  std::optional<model::TransitionMatrix> matrix =
      tra.collector.finish(tra.num_states, k, values, duplicates);
  for (const DistributionCollector::Duplicate& duplicate : duplicates) {
    if (diagnostics.should_stop()) break;
    report_duplicate(diagnostics, files.transitions, tra, duplicate);
  }
  return matrix;
}

// From the "init" label of .lab, else the "- - s -" lines of .tra, else state 0 (PRISM's
// own defaults). When both files list initial states they must agree.
// Every label of .lab is kept as an atomic proposition (model/state_labels.hpp), "init" too, as
// Storm keeps it.
void read_initial_states(const PrismFiles& files, DiagnosticEngine& diagnostics,
                         const PrismTransitions& tra, std::vector<StateIndex>& initial,
                         model::StateLabels& labels) {
  bool found = false;
  if (files.labels) {
    if (!read_prism_labels(*files.labels, diagnostics, tra.num_states, initial, labels, found))
      return;
    std::sort(initial.begin(), initial.end());
    initial.erase(std::unique(initial.begin(), initial.end()), initial.end());
  }
  std::vector<StateIndex> from_tra = tra.initial;
  std::sort(from_tra.begin(), from_tra.end());
  from_tra.erase(std::unique(from_tra.begin(), from_tra.end()), from_tra.end());
  if (found && tra.has_initial_lines && from_tra != initial) {
    diagnostics.error(
        SourceLocation{*files.labels, 0},
        "the \"init\" label disagrees with the initial states of the transitions file");
    return;
  }
  if (found) return;
  if (files.labels) {
    diagnostics.warning(SourceRange{{*files.labels, 0}, 1},
                        tra.has_initial_lines
                            ? "no \"init\" label; the transitions file gives the initial states"
                            : "no \"init\" label; state 0 is the initial state");
  }
  initial = tra.has_initial_lines ? from_tra : std::vector<StateIndex>{0};
}

model::Context read_rewards(const PrismFiles& files, DiagnosticEngine& diagnostics,
                            const PrismTransitions& tra, ValueCache& values) {
  model::Context context;
  context.name = "default";
  context.rewards.state.assign(tra.num_states, RationalPool::kZero);
  if (files.state_rewards) {
    read_prism_state_rewards(*files.state_rewards, diagnostics, tra.num_states, values,
                             context.rewards.state);
  }
  if (files.transition_rewards) {
    const auto k = static_cast<std::uint32_t>(tra.actions.size());
    context.rewards.choice.assign(std::size_t{tra.num_states} * k, RationalPool::kZero);
    read_prism_transition_rewards(*files.transition_rewards, diagnostics, tra.num_states, k,
                                  ChoiceTable(tra), tra.markov_chain, values,
                                  context.rewards.choice);
  }
  return context;
}

}  // namespace

std::string unlabelled_action_name(std::uint32_t choice) {
  return "[" + std::to_string(choice) + "]";
}

std::optional<model::ExplicitModel> read_prism(const PrismFiles& files,
                                               DiagnosticEngine& diagnostics,
                                               const ReadOptions& options) {
  const std::size_t errors = diagnostics.error_count();
  model::ExplicitModel model;
  ValueCache values(model.values, options.max_number_bits);
  PrismTransitions tra;
  if (!read_prism_transitions(files.transitions, diagnostics, options, values, tra))
    return std::nullopt;
  if (diagnostics.should_stop()) return std::nullopt;
  model.name =
      std::filesystem::path(diagnostics.sources().file(files.transitions).path()).stem().string();
  model.states.size = tra.num_states;
  model.type = tra.markov_chain ? model::ModelType::kDtmc : model::ModelType::kMdp;
  model.actions = tra.actions;
  model::Context context = read_rewards(files, diagnostics, tra, values);
  std::optional<model::TransitionMatrix> matrix =
      build_matrix(files, diagnostics, tra, model.values);
  if (files.states && !diagnostics.should_stop()) {
    read_prism_states(*files.states, diagnostics, model.states);
  }
  if (!diagnostics.should_stop())
    read_initial_states(files, diagnostics, tra, model.states.initial, model.labels);
  if (!matrix || diagnostics.error_count() != errors) return std::nullopt;
  context.transitions = std::make_shared<const model::TransitionMatrix>(std::move(*matrix));
  model.contexts.push_back(std::move(context));
  return model;
}

}  // namespace oasis::formats
