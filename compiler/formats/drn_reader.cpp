// The DRN reader (drn_reader.hpp): the header, then the states in order, each with its
// choices and their transitions, checked line by line and reported where they are wrong.

#include "formats/drn_reader.hpp"

#include <algorithm>
#include <filesystem>
#include <string_view>
#include <unordered_map>

#include "formats/exact_sum.hpp"
#include "formats/explicit_parts.hpp"
#include "formats/explicit_reader.hpp"
#include "formats/model_size.hpp"

namespace oasis::formats {
namespace {

using model::ActionIndex;
using model::StateIndex;

// Storm's name for a choice without a label.
constexpr std::string_view kNoLabel = "__NOLABEL__";

struct Header {
  bool has_type = false;
  model::ModelType type = model::ModelType::kMdp;
  std::vector<std::string> reward_models;
  bool has_states = false;
  std::uint32_t num_states = 0;
  std::string_view states_text;  // the count as written, for diagnostics
  std::optional<std::uint64_t> num_choices;
  const char* choices_line = nullptr;
  const char* model_line = nullptr;
};

// A choice reward of one reward model, kept until the action set is complete.
struct ChoiceReward {
  StateIndex state;
  ActionIndex action;
  ValueId value;
};

std::string_view trimmed(std::string_view text) {
  while (!text.empty() && TextScanner::is_blank(text.front()))
    text.remove_prefix(1);
  while (!text.empty() && TextScanner::is_blank(text.back()))
    text.remove_suffix(1);
  return text;
}

bool starts_with_word(std::string_view line, std::string_view word) {
  return line.size() > word.size() && line.starts_with(word) &&
         TextScanner::is_blank(line[word.size()]);
}

bool has_control_character(std::string_view name) {
  for (const char c : name) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte == 0x7f) return true;
  }
  return false;
}

class DrnReader {
 public:
  DrnReader(FileId file, DiagnosticEngine& diagnostics, const ReadOptions& options,
            model::ExplicitModel& model)
      : scan_(file, diagnostics),
        options_(options),
        model_(model),
        values_(model.values, options.max_number_bits) {}

  bool read() {
    const std::size_t errors = scan_.diagnostics().error_count();
    if (!read_header()) return false;
    state_rewards_.assign(header_.reward_models.size(),
                          std::vector<ValueId>(header_.num_states, RationalPool::kZero));
    choice_rewards_.resize(header_.reward_models.size());
    while (next_line() && !scan_.diagnostics().should_stop()) {
      read_body_line();
      scan_.skip_line();
      if (collector_.full()) {
        scan_.error_here("the file has more than 2^32 transitions");
        break;
      }
    }
    close_choice();
    check_counts();
    if (scan_.diagnostics().error_count() != errors) return false;
    build();
    return scan_.diagnostics().error_count() == errors;
  }

 private:
  // Skips blank lines and "//" comments; false at the end of the file.
  bool next_line() {
    for (;;) {
      scan_.skip_blank_lines();
      scan_.skip_blanks();
      if (scan_.at_end()) return false;
      if (!scan_.rest_of_line().starts_with("//")) return true;
      scan_.skip_line();
    }
  }

  // --- The header ---------------------------------------------------------------------

  bool read_header() {
    for (;;) {
      if (!next_line()) {
        scan_.error_here("the file ends before '@model'");
        return false;
      }
      const char* line = scan_.position();
      const std::string_view text = trimmed(scan_.rest_of_line());
      if (text == "@model") {
        header_.model_line = line;
        scan_.skip_line();
        return check_header(line);
      }
      if (!read_header_line(line, text)) return false;
      scan_.skip_line();
    }
  }

  bool read_header_line(const char* line, std::string_view text) {
    if (text.starts_with("@type:")) return read_type(line, text.substr(6));
    if (text.starts_with("@value_type:")) return read_value_type(line, text.substr(12));
    if (text == "@parameters") return read_parameters();
    if (text == "@reward_models") return read_reward_models();
    if (text == "@nr_states") return read_number_of_states();
    if (text == "@nr_choices") return read_number_of_choices();
    if (text == "@placeholders") {
      scan_.error_at(line, text.size(),
                     "placeholders are not supported: they belong to parametric models");
      return false;
    }
    scan_.error_at(line, text.size(),
                   "unknown header line '" + std::string(text) +
                       "': expected @type, @value_type, @parameters, @reward_models, "
                       "@nr_states, @nr_choices or @model");
    return false;
  }

  bool read_type(const char* line, std::string_view value) {
    const std::string_view type = trimmed(value);
    if (header_.has_type) {
      scan_.error_at(line, 5, "the model type is given twice");
      return false;
    }
    header_.has_type = true;
    if (type == "DTMC" || type == "MDP") {
      header_.type = type == "DTMC" ? model::ModelType::kDtmc : model::ModelType::kMdp;
      return true;
    }
    const bool known = type == "CTMC" || type == "Markov Automaton" || type == "POMDP" ||
                       type == "S2PG" || type == "SMG";
    scan_.error_at(line, scan_.rest_of_line().size(),
                   (known ? "a " + std::string(type) + " is not supported"
                          : "unknown model type '" + std::string(type) + "'") +
                       ": oasis reads DTMCs and MDPs");
    return false;
  }

  bool read_value_type(const char* line, std::string_view value) {
    const std::string_view type = trimmed(value);
    if (type == "double" || type == "rational") return true;
    scan_.error_at(line, scan_.rest_of_line().size(),
                   "value type '" + std::string(type) +
                       "' is not supported: oasis reads exact numbers (double or rational)");
    return false;
  }

  // Storm reads the line after "@parameters" as the parameters, whatever it holds.
  bool read_parameters() {
    scan_.skip_line();
    scan_.skip_blanks();
    if (scan_.at_line_end()) return true;
    scan_.error_at(scan_.position(), scan_.rest_of_line().size(),
                   "parametric models are not supported: the line after '@parameters' must be "
                   "empty");
    return false;
  }

  bool read_reward_models() {
    scan_.skip_line();
    for (;;) {
      scan_.skip_blanks();
      if (scan_.at_line_end()) return true;
      const char* token = scan_.position();
      const std::string name(scan_.read_word());
      if (has_control_character(name)) {  // a name the writer could not give back
        scan_.error_at(token, name.size(), "a reward model's name holds a control character");
        return false;
      }
      for (const std::string& other : header_.reward_models) {
        if (other == name) {
          scan_.error_at(token, name.size(), "reward model '" + name + "' is named twice");
          return false;
        }
      }
      header_.reward_models.push_back(name);
    }
  }

  // The number on the line after a header keyword; `text` is its digits.
  bool read_count(const char* what, std::uint64_t& count, std::string_view& text) {
    scan_.skip_line();
    scan_.skip_blanks();
    const Natural number = scan_.read_natural();
    if (number.empty()) {
      scan_.error_here(std::string("expected ") + what);
      return false;
    }
    count = number.overflow ? UINT64_MAX : number.value;
    text = number.text;
    return scan_.expect_line_end(what);
  }

  bool read_number_of_states() {
    std::uint64_t count = 0;
    std::string_view text;
    if (!read_count("the number of states", count, text)) return false;
    if (count == 0) {
      scan_.error_at(text.data(), text.size(), "the model has no states");
      return false;
    }
    if (const auto refusal = state_count_refusal(text, count, options_)) {
      scan_.error_at(text.data(), text.size(), "the file declares " + *refusal);
      return false;
    }
    header_.has_states = true;
    header_.num_states = static_cast<std::uint32_t>(count);
    header_.states_text = text;
    return true;
  }

  bool read_number_of_choices() {
    std::uint64_t count = 0;
    std::string_view text;
    if (!read_count("the number of choices", count, text)) return false;
    header_.num_choices = count;
    header_.choices_line = text.data();
    return true;
  }

  bool check_header(const char* line) {
    if (!header_.has_type) scan_.error_at(line, 6, "'@type' must come before '@model'");
    if (!header_.has_states) scan_.error_at(line, 6, "'@nr_states' must come before '@model'");
    return header_.has_type && header_.has_states && fits_memory_budget();
  }

  // Once the header is read and before the body is, or anything is allocated for its states:
  // a model whose reading alone would not fit the memory budget is refused at its state count
  // (with '@nr_choices' when the file gives it; the edges are not declared).
  bool fits_memory_budget() {
    const DeclaredSize size{.states = header_.num_states,
                            .choices = header_.num_choices.value_or(0)};
    const std::optional<std::string> refusal = memory_refusal(size, options_);
    if (!refusal) return true;
    std::string declared = std::string(header_.states_text) + " states";
    if (header_.num_choices)
      declared += " and " + std::to_string(*header_.num_choices) + " choices";
    scan_.error_at(header_.states_text.data(), header_.states_text.size(),
                   "the file declares " + declared + ": " + *refusal);
    return false;
  }

  // --- The states -----------------------------------------------------------------------

  void read_body_line() {
    const std::string_view line = scan_.rest_of_line();
    if (starts_with_word(line, "state") || line == "state") {
      read_state_line();
    } else if (starts_with_word(line, "action") || line == "action") {
      read_action_line();
    } else {
      read_transition_line();
    }
  }

  void read_state_line() {
    close_choice();
    state_ok_ = false;
    scan_.seek(scan_.position() + 5);
    scan_.skip_blanks();
    const char* token = scan_.position();
    const Natural number = scan_.read_natural();
    if (number.empty()) {
      scan_.error_here("expected the state's number");
      return;
    }
    if (states_seen_ >= header_.num_states) {
      scan_.error_at(
          token, number.text.size(),
          "more states than '@nr_states' declares (" + std::to_string(header_.num_states) + ")");
      return;
    }
    if (number.overflow || number.value != states_seen_) {
      scan_.error_at(token, number.text.size(),
                     "expected state " + std::to_string(states_seen_) + ", not " +
                         std::string(number.text) + ": states are listed 0, 1, 2, ... in order");
      return;
    }
    state_ = states_seen_++;
    choices_in_state_ = 0;
    state_ok_ = true;
    scan_.skip_blanks();
    if (scan_.peek() == '[') {
      std::vector<ValueId> rewards;
      if (!read_reward_list(rewards)) return;
      for (std::size_t r = 0; r < rewards.size(); ++r)
        state_rewards_[r][state_] = rewards[r];
    }
    read_labels();
  }

  // "[r1, r2, ...]": one value per reward model, in @reward_models' order.
  bool read_reward_list(std::vector<ValueId>& rewards) {
    const char* open = scan_.position();
    scan_.consume('[');
    for (;;) {
      scan_.skip_blanks();
      const char* token = scan_.position();
      const char* stop = token;
      while (stop < scan_.end() && *stop != ',' && *stop != ']' && *stop != '\n' &&
             !TextScanner::is_blank(*stop)) {
        ++stop;
      }
      scan_.seek(stop);
      const std::string_view text(token, static_cast<std::size_t>(stop - token));
      const std::optional<ValueId> value = read_value(token, text, "reward");
      if (!value) return false;
      rewards.push_back(*value);
      scan_.skip_blanks();
      if (scan_.consume(',')) continue;
      if (scan_.consume(']')) break;
      scan_.error_here("expected ',' or ']' in the list of rewards");
      return false;
    }
    if (rewards.size() == header_.reward_models.size()) return true;
    scan_.error_at(open, static_cast<std::size_t>(scan_.position() - open),
                   std::to_string(rewards.size()) + (rewards.size() == 1 ? " reward" : " rewards") +
                       " here, but '@reward_models' names " +
                       std::to_string(header_.reward_models.size()));
    return false;
  }

  std::optional<ValueId> read_value(const char* token, std::string_view text, const char* what) {
    if (text.empty()) {
      scan_.error_at(token, 1, std::string("expected the ") + what);
      return std::nullopt;
    }
    const std::optional<ValueId> id = values_.intern_text(text);
    if (!id) {
      scan_.error_at(token, text.size(),
                     std::string(what) + " '" + std::string(text) + "' is not a number");
      return std::nullopt;
    }
    if (!values_.check_carried(*id, what, scan_.range_at(token, text.size()),
                               scan_.diagnostics())) {
      return std::nullopt;
    }
    return id;
  }

  // Blank-separated labels, each bare or in double quotes (Storm quotes those with blanks).
  void read_labels() {
    for (;;) {
      scan_.skip_blanks();
      if (scan_.at_line_end()) return;
      const char* token = scan_.position();
      std::string_view name;
      if (scan_.consume('"')) {
        const char* start = scan_.position();
        while (!scan_.at_line_end() && scan_.peek() != '"')
          scan_.seek(scan_.position() + 1);
        if (!scan_.consume('"')) {
          scan_.error_at(token, 1, "label not closed by '\"' on its line");
          return;
        }
        name = std::string_view(start, static_cast<std::size_t>(scan_.position() - 1 - start));
      } else {
        name = scan_.read_word();
      }
      if (!check_label(token, name)) return;
      labels_.emplace_back(state_, label_index(name));
    }
  }

  bool check_label(const char* token, std::string_view name) {
    const std::size_t length = static_cast<std::size_t>(scan_.position() - token);
    if (name.empty()) {
      scan_.error_at(token, length, "a label is empty");
      return false;
    }
    if (has_control_character(name) || name.find('"') != std::string_view::npos) {
      scan_.error_at(token, length, "a label holds a '\"' or a control character");
      return false;
    }
    return true;
  }

  std::uint32_t label_index(std::string_view name) {
    const auto [it, inserted] = label_indices_.try_emplace(
        std::string(name), static_cast<std::uint32_t>(label_names_.size()));
    if (inserted) label_names_.emplace_back(name);
    return it->second;
  }

  // --- Choices and transitions ----------------------------------------------------------

  void read_action_line() {
    close_choice();
    const char* line = scan_.position();
    if (!state_ok_) {
      if (states_seen_ == 0) scan_.error_at(line, 6, "an 'action' before the first 'state'");
      return;
    }
    scan_.seek(line + 6);
    scan_.skip_blanks();
    const std::string_view name = scan_.read_word();
    if (name.empty()) {
      scan_.error_here("expected the action's name");
      return;
    }
    if (has_control_character(name)) {  // a name the writer could not give back
      scan_.error_here("an action name holds a control character");
      return;
    }
    const std::uint32_t j = choices_in_state_++;
    if (header_.type == model::ModelType::kDtmc && j > 0) {
      scan_.error_at(line, 6,
                     "state " + std::to_string(state_) +
                         " has a second choice here, but a DTMC has one per state");
      return;
    }
    const ActionIndex action = action_index(action_name(name, j));
    scan_.skip_blanks();
    std::vector<ValueId> rewards;
    if (scan_.peek() == '[' && !read_reward_list(rewards)) return;
    if (!scan_.expect_line_end("the action")) return;
    for (std::size_t r = 0; r < rewards.size(); ++r) {
      if (rewards[r] != RationalPool::kZero)
        choice_rewards_[r].push_back({state_, action, rewards[r]});
    }
    collector_.begin(state_, action, scan_.offset_of(line), j);
    open_ = true;
    choice_ok_ = true;
    choice_edges_ = 0;
    choice_ = j;
    sum_.reset();
    ++num_choices_;
  }

  [[nodiscard]] std::string action_name(std::string_view name, std::uint32_t j) const {
    if (header_.type == model::ModelType::kDtmc) return unlabelled_action_name(0);
    if (name == kNoLabel) return unlabelled_action_name(j);
    return std::string(name);
  }

  ActionIndex action_index(const std::string& name) {
    const auto [it, inserted] =
        action_indices_.try_emplace(name, static_cast<ActionIndex>(model_.actions.size()));
    if (inserted) model_.actions.push_back(name);
    return it->second;
  }

  void read_transition_line() {
    const char* line = scan_.position();
    if (!open_) {
      if (state_ok_ || states_seen_ == 0) {
        scan_.error_at(line, 1, "a transition before the 'action' it belongs to");
      }
      return;
    }
    StateIndex target = 0;
    if (!scan_.read_state(header_.num_states, "the target state", target)) return fail_choice();
    scan_.skip_blanks();
    if (!scan_.expect(':', "expected ':' between the target state and its probability"))
      return fail_choice();
    scan_.skip_blanks();
    const char* token = scan_.position();
    const std::string_view text = scan_.read_word();
    const std::optional<ValueId> probability = read_value(token, text, "probability");
    if (!probability) return fail_choice();
    if (sgn(values_.pool()[*probability]) <= 0) {
      scan_.error_at(token, text.size(), "probability must be positive");
      return fail_choice();
    }
    if (!scan_.expect_line_end("the probability")) return fail_choice();
    collector_.add(target, *probability);
    sum_.add(*probability, values_);
    ++choice_edges_;
  }

  void fail_choice() { choice_ok_ = false; }

  // Checks the sum of the choice that just ended.
  void close_choice() {
    if (!open_) return;
    open_ = false;
    if (!choice_ok_) return;
    const std::uint32_t d = static_cast<std::uint32_t>(collector_.size() - 1);
    const SourceLocation where{scan_.file(), collector_.offset(d)};
    const std::string choice =
        "state " + std::to_string(state_) + ", choice " + std::to_string(choice_);
    if (choice_edges_ == 0) {
      scan_.diagnostics().error(where, choice + " has no transitions");
      return;
    }
    if (sum_.compare_to_one() == 0) return;
    const Rational sum = sum_.value();
    if (options_.tolerance && abs(sum - 1) <= *options_.tolerance) return;
    scan_.diagnostics().error(
        where, "probabilities of " + choice + " sum to " + describe(sum) + ", not 1");
  }

  void check_counts() {
    if (scan_.diagnostics().should_stop()) return;
    if (states_seen_ != header_.num_states) {
      scan_.error_at(header_.model_line, 6,
                     "'@nr_states' declares " + std::to_string(header_.num_states) +
                         " states but the file lists " + std::to_string(states_seen_));
    }
    if (header_.num_choices && *header_.num_choices != num_choices_) {
      scan_.error_at(header_.choices_line, 1,
                     "'@nr_choices' declares " + std::to_string(*header_.num_choices) +
                         " choices but the file has " + std::to_string(num_choices_));
    }
  }

  // --- The model ------------------------------------------------------------------------

  void build() {
    const std::uint32_t n = header_.num_states;
    const auto k = static_cast<std::uint32_t>(model_.actions.size());
    if (std::uint64_t{n} * k >= UINT32_MAX) {
      scan_.error_at(header_.model_line, 6,
                     std::to_string(n) + " states and " + std::to_string(k) +
                         " actions make more than 2^32 state-action pairs");
      return;
    }
    std::vector<DistributionCollector::Duplicate> duplicates;
    std::optional<model::TransitionMatrix> matrix =
        collector_.finish(n, k, model_.values, duplicates);
    for (const DistributionCollector::Duplicate& duplicate : duplicates)
      report_duplicate(duplicate);
    if (!matrix) return;
    model_.name = std::filesystem::path(scan_.path()).stem().string();
    model_.type = header_.type;
    model_.states.size = n;
    build_labels();
    build_contexts(std::make_shared<const model::TransitionMatrix>(std::move(*matrix)));
  }

  void report_duplicate(const DistributionCollector::Duplicate& duplicate) {
    const StateIndex state = collector_.source(duplicate.first);
    const std::string& action = model_.actions[collector_.action(duplicate.first)];
    const SourceLocation first{scan_.file(), collector_.offset(duplicate.first)};
    const SourceLocation second{scan_.file(), collector_.offset(duplicate.second)};
    scan_.diagnostics().error(
        second, "state " + std::to_string(state) + " has two choices named '" + action +
                    "' (choices " + std::to_string(collector_.payload(duplicate.first)) + " and " +
                    std::to_string(collector_.payload(duplicate.second)) +
                    "); an MDP allows one per action");
    scan_.diagnostics().note(first, "the first is here");
  }

  // Labels as atomic propositions, "init" among them; its states are the initial states.
  void build_labels() {
    model::StateLabelsBuilder builder(label_names_);
    for (const auto& [state, label] : labels_)
      builder.add(state, label);
    model_.labels = builder.finish(model_.states.size);
    const auto init = label_indices_.find("init");
    if (init != label_indices_.end()) {
      for (const auto& [state, label] : labels_) {
        if (label == init->second) model_.states.initial.push_back(state);
      }
      std::sort(model_.states.initial.begin(), model_.states.initial.end());
      model_.states.initial.erase(
          std::unique(model_.states.initial.begin(), model_.states.initial.end()),
          model_.states.initial.end());
      return;
    }
    scan_.diagnostics().warning(scan_.range_at(header_.model_line, 6),
                                "no state is labelled \"init\"; state 0 is the initial state");
    model_.states.initial = {0};
  }

  void build_contexts(const std::shared_ptr<const model::TransitionMatrix>& matrix) {
    if (header_.reward_models.empty()) {
      model::Context context;
      context.name = "default";
      context.transitions = matrix;
      context.rewards.state.assign(header_.num_states, RationalPool::kZero);
      model_.contexts.push_back(std::move(context));
      return;
    }
    const std::size_t k = model_.actions.size();
    for (std::size_t r = 0; r < header_.reward_models.size(); ++r) {
      model::Context context;
      context.name = header_.reward_models[r];
      context.transitions = matrix;
      context.rewards.state = std::move(state_rewards_[r]);
      if (!choice_rewards_[r].empty()) {
        context.rewards.choice.assign(header_.num_states * k, RationalPool::kZero);
        for (const ChoiceReward& reward : choice_rewards_[r])
          context.rewards.choice[reward.state * k + reward.action] = reward.value;
      }
      model_.contexts.push_back(std::move(context));
    }
  }

  PrismScanner scan_;
  const ReadOptions& options_;
  model::ExplicitModel& model_;
  ValueCache values_;
  Header header_;
  DistributionCollector collector_;
  ExactSum sum_;
  std::unordered_map<std::string, ActionIndex> action_indices_;
  std::vector<std::string> label_names_;
  std::unordered_map<std::string, std::uint32_t> label_indices_;
  std::vector<std::pair<StateIndex, std::uint32_t>> labels_;
  std::vector<std::vector<ValueId>> state_rewards_;        // per reward model, per state
  std::vector<std::vector<ChoiceReward>> choice_rewards_;  // per reward model
  std::uint32_t states_seen_ = 0;
  std::uint64_t num_choices_ = 0;
  // The state and choice being read.
  bool state_ok_ = false;
  StateIndex state_ = 0;
  std::uint32_t choices_in_state_ = 0;
  bool open_ = false;
  bool choice_ok_ = false;
  std::uint32_t choice_ = 0;
  std::uint64_t choice_edges_ = 0;
};

}  // namespace

std::optional<model::ExplicitModel> read_drn(FileId file, DiagnosticEngine& diagnostics,
                                             const ReadOptions& options) {
  model::ExplicitModel model;
  if (!DrnReader(file, diagnostics, options, model).read()) return std::nullopt;
  return model;
}

}  // namespace oasis::formats
