// The UMB reader (umb_reader.hpp): the archive, its index, then each array checked against
// the index's counts before anything is built from it. Every size comes from an entry that is
// already in memory (and bounded by --max-input-size) or from a count the index checked, so a
// hostile header allocates nothing; the first problem is reported, naming its entry, and ends
// the reading.

#include "formats/umb_reader.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <unordered_map>

#include "formats/distribution_collector.hpp"
#include "formats/exact_sum.hpp"
#include "formats/explicit_reader.hpp"
#include "formats/umb_archive.hpp"
#include "formats/umb_binary.hpp"
#include "formats/umb_index.hpp"
#include "formats/umb_valuations.hpp"
#include "formats/value_cache.hpp"
#include "support/double_range.hpp"

namespace oasis::formats {
namespace {

using model::ActionIndex;
using model::StateIndex;

class UmbReader {
 public:
  UmbReader(FileId file, DiagnosticEngine& diagnostics, const ReadOptions& options,
            model::ExplicitModel& model)
      : diagnostics_(diagnostics),
        options_(options),
        model_(model),
        values_(model.values, options.max_number_bits),
        path_(diagnostics.sources().file(file).path()),
        bytes_(diagnostics.sources().file(file).text()) {}

  bool read() {
    std::vector<UmbEntry> entries;
    std::string error;
    if (!read_umb_archive(bytes_, options_.max_bytes, entries, error)) return fail(error);
    for (UmbEntry& entry : entries)
      entries_.emplace(std::move(entry.name), std::move(entry.bytes));
    const std::string* index = entry("index.json");
    if (index == nullptr) return fail("the archive has no index.json");
    if (!read_umb_index(*index, options_, index_, error)) return fail(error);
    return read_structure() && read_probabilities() && read_initial_states() && read_actions() &&
           read_choices() && read_labels() && read_rewards() && build() && read_valuations();
  }

 private:
  bool fail(const std::string& message) {
    diagnostics_.file_error(path_, message);
    return false;
  }

  [[nodiscard]] const std::string* entry(const std::string& name) const {
    const auto it = entries_.find(name);
    return it == entries_.end() ? nullptr : &it->second;
  }

  // Whether `bytes` holds `count` items of `item_bytes` bytes; reports it when not.
  bool check_size(const std::string& name, const std::string& bytes, std::uint64_t count,
                  std::uint64_t item_bytes, const std::string& counted) {
    if (bytes.size() % item_bytes == 0 && bytes.size() / item_bytes == count) return true;
    return fail(name + ": holds " + std::to_string(bytes.size()) + " bytes, but " + counted +
                " needs " + std::to_string(count) + " values of " + std::to_string(item_bytes) +
                " bytes");
  }

  // A CSR file: n + 1 offsets from 0 to `total`, never decreasing. Absent, it maps each i to
  // [i, i], which needs total == n.
  bool read_csr(const std::string& name, std::uint64_t n, std::uint64_t total, const char* from,
                const char* to, std::vector<std::uint32_t>& offsets) {
    const std::string* bytes = entry(name);
    if (bytes == nullptr) {
      if (n != total) {
        return fail(name + ": absent, which gives each of the " + std::to_string(n) + " " + from +
                    " one of the " + std::to_string(total) + " " + to);
      }
      offsets.resize(n + 1);
      for (std::uint64_t i = 0; i <= n; ++i)
        offsets[i] = static_cast<std::uint32_t>(i);
      return true;
    }
    if (!check_size(name, *bytes, n + 1, 8, std::to_string(n) + " " + from + " (and the end)"))
      return false;
    offsets.resize(n + 1);
    for (std::uint64_t i = 0; i <= n; ++i) {
      const std::uint64_t offset = umb::load_u64(*bytes, i);
      const std::uint64_t before = i == 0 ? 0 : offsets[i - 1];
      if (offset < before || offset > total || (i == 0 && offset != 0) ||
          (i == n && offset != total)) {
        return fail(name + ": offset " + std::to_string(i) + " is " + std::to_string(offset) +
                    "; the offsets must rise from 0 to " + std::to_string(total) + " (the " + to +
                    ")");
      }
      offsets[i] = static_cast<std::uint32_t>(offset);
    }
    return true;
  }

  // --- The transition system -------------------------------------------------------------

  bool read_structure() {
    // The probabilities back the counts: what is built per choice and per branch below is
    // never larger than this entry, which is in memory.
    const std::string probabilities = "branch-to-probability.bin";
    const std::string* bytes_of_probabilities = entry(probabilities);
    if (bytes_of_probabilities == nullptr)
      return fail(probabilities + ": absent, but the model needs its probabilities");
    if (!check_size(probabilities, *bytes_of_probabilities, index_.num_branches,
                    index_.probability.bits / 8, "\"#branches\"")) {
      return false;
    }
    if (index_.num_choices > index_.num_branches) {
      return fail("index.json: \"#choices\" is " + std::to_string(index_.num_choices) +
                  " but \"#branches\" only " + std::to_string(index_.num_branches) +
                  ": every choice needs a branch");
    }
    if (!read_csr("state-to-choices.bin", index_.num_states, index_.num_choices, "states",
                  "choices", state_choices_) ||
        !read_csr("choice-to-branches.bin", index_.num_choices, index_.num_branches, "choices",
                  "branches", choice_branches_)) {
      return false;
    }
    if (index_.markov_chain) {
      for (StateIndex s = 0; s < index_.num_states; ++s) {
        if (state_choices_[s + 1] - state_choices_[s] > 1) {
          return fail("state-to-choices.bin: state " + std::to_string(s) + " has " +
                      std::to_string(state_choices_[s + 1] - state_choices_[s]) +
                      " choices, but a DTMC (\"#players\": 0) has one per state");
        }
      }
    }
    const std::string name = "branch-to-target.bin";
    const std::string* bytes = entry(name);
    targets_.assign(index_.num_branches, 0);  // absent: every branch goes to state 0
    if (bytes == nullptr) return true;
    if (!check_size(name, *bytes, index_.num_branches, 8, "\"#branches\"")) return false;
    for (std::uint64_t b = 0; b < index_.num_branches; ++b) {
      const std::uint64_t target = umb::load_u64(*bytes, b);
      if (target >= index_.num_states) {
        return fail(name + ": " + branch(b) + " goes to state " + std::to_string(target) +
                    ", but the model has " + std::to_string(index_.num_states) + " states");
      }
      targets_[b] = static_cast<StateIndex>(target);
    }
    return true;
  }

  // "branch 7 (state 2, choice 1)": where a branch is, for messages.
  [[nodiscard]] std::string branch(std::uint64_t b) const {
    const auto c = static_cast<std::uint64_t>(
        std::upper_bound(choice_branches_.begin(), choice_branches_.end(), b) -
        choice_branches_.begin() - 1);
    return "branch " + std::to_string(b) + " (" + choice(c) + ")";
  }
  // "state 2, choice 1": choice c by its state and its place there.
  [[nodiscard]] std::string choice(std::uint64_t c) const {
    const auto s = static_cast<std::uint64_t>(
        std::upper_bound(state_choices_.begin(), state_choices_.end(), c) - state_choices_.begin() -
        1);
    return "state " + std::to_string(s) + ", choice " + std::to_string(c - state_choices_[s]);
  }

  // --- Numbers ---------------------------------------------------------------------------

  // `count` numbers of `type` from `name`, which must be present: the format would read an
  // absent array as zeros, but an index that names many such arrays would then make a model
  // far larger than its file.
  bool read_numbers(const std::string& name, const umb::ValueType& type, std::uint64_t count,
                    const char* what, std::vector<ValueId>& out) {
    const std::string* bytes = entry(name);
    if (bytes == nullptr) return fail(name + ": absent, though the index says it is there");
    const std::uint64_t item = type.bits / 8;
    if (!check_size(name, *bytes, count, item, "the index (" + type.name + ")")) return false;
    out.resize(count);
    for (std::uint64_t i = 0; i < count; ++i) {
      const std::string_view value = std::string_view(*bytes).substr(i * item, item);
      const std::optional<ValueId> id =
          type.name == "double" ? double_value(name, value, i) : rational_value(name, value, i);
      if (!id || !check_value(name, *id, i, what)) return false;
      out[i] = *id;
    }
    return true;
  }

  std::optional<ValueId> double_value(const std::string& name, std::string_view bytes,
                                      std::uint64_t i) {
    const std::uint64_t raw = umb::load_u64(bytes, 0);
    const auto cached = doubles_.find(raw);
    if (cached != doubles_.end()) return cached->second;
    const double value = umb::load_double(bytes);
    if (!std::isfinite(value)) {
      fail(name + ": value " + std::to_string(i) + " is not a finite number");
      return std::nullopt;
    }
    const std::optional<ValueId> id = values_.intern_text(umb::shortest_decimal(value));
    if (!id) {
      fail(name + ": value " + std::to_string(i) + " cannot be read as a decimal");
      return std::nullopt;
    }
    doubles_.emplace(raw, *id);
    return id;
  }

  std::optional<ValueId> rational_value(const std::string& name, std::string_view bytes,
                                        std::uint64_t i) {
    if (bytes.size() == 16) {  // the common size: 64-bit parts, without GMP when positive
      const std::uint64_t numerator = umb::load_u64(bytes, 0);
      const std::uint64_t denominator = umb::load_u64(bytes, 1);
      if (denominator != 0 && numerator >> 63 == 0)
        return values_.intern_fraction(numerator, denominator);
    }
    const std::optional<Rational> value = umb::load_rational(bytes, bytes.size() * 8);
    if (!value) {
      fail(name + ": value " + std::to_string(i) + " has the denominator 0");
      return std::nullopt;
    }
    if (bit_size(*value) > options_.max_number_bits) {
      fail(name + ": value " + std::to_string(i) + " " +
           too_long_message(*value, options_.max_number_bits));
      return std::nullopt;
    }
    return values_.intern(*value);
  }

  // The number-size limit, and whether a catalog can carry the value (support/double_range),
  // judged once per distinct value.
  bool check_value(const std::string& name, ValueId id, std::uint64_t i, const char* what) {
    if (judged_.size() <= id) judged_.resize(std::size_t{id} + 1, 0);
    if (judged_[id] != 0) return true;
    const Rational& value = values_.pool()[id];
    if (bit_size(value) > options_.max_number_bits) {
      return fail(name + ": value " + std::to_string(i) + " " +
                  too_long_message(value, options_.max_number_bits));
    }
    const DoubleFit fit = double_fit(value);
    const std::string message = carried_value_message(value, fit, what);
    if (fit == DoubleFit::kUnderflow || fit == DoubleFit::kOverflow)
      return fail(name + ": value " + std::to_string(i) + ": " + message);
    if (fit == DoubleFit::kSubnormal)
      diagnostics_.file_warning(path_, name + ": value " + std::to_string(i) + ": " + message);
    judged_[id] = 1;
    return true;
  }

  bool read_probabilities() {
    return read_numbers("branch-to-probability.bin", index_.probability, index_.num_branches,
                        "the probability", probabilities_);
  }

  // --- Initial states, actions, labels -------------------------------------------------

  // A bitset of `n` values from `name`, into the indices of its set bits; absent, none.
  bool read_bitset(const std::string& name, std::uint64_t n, std::vector<StateIndex>& set) {
    const std::string* bytes = entry(name);
    if (bytes == nullptr) return true;
    if (bytes->size() != umb::bitset_bytes(n)) {
      return fail(name + ": holds " + std::to_string(bytes->size()) + " bytes, but a bitset of " +
                  std::to_string(n) + " states has " + std::to_string(umb::bitset_bytes(n)));
    }
    for (std::uint64_t i = 0; i < n; ++i) {
      if (umb::load_bit(*bytes, i)) set.push_back(static_cast<StateIndex>(i));
    }
    return true;
  }

  bool read_initial_states() {
    const std::string name = "state-is-initial.bin";
    if (!read_bitset(name, index_.num_states, initial_)) return false;
    if (initial_.size() != index_.num_initial_states) {
      return fail(name + ": " +
                  (entry(name) == nullptr
                       ? "absent, so no state is initial"
                       : std::to_string(initial_.size()) + " states are initial") +
                  ", but \"#initial-states\" is " + std::to_string(index_.num_initial_states));
    }
    if (initial_.empty()) {
      diagnostics_.file_warning(path_, "no state is initial; state 0 is the initial state");
      initial_.push_back(0);
    }
    return true;
  }

  // The action strings of the choices: actions/choices/.
  bool read_actions() {
    const std::uint64_t k = index_.num_choice_actions;
    if (index_.markov_chain || k == 0) return true;
    const std::string values = "actions/choices/values.bin";
    choice_actions_.assign(index_.num_choices, 0);
    if (const std::string* bytes = entry(values)) {
      if (!check_size(values, *bytes, index_.num_choices, 4, "\"#choices\"")) return false;
      for (std::uint64_t c = 0; c < index_.num_choices; ++c) {
        choice_actions_[c] = umb::load_u32(*bytes, c);
        if (choice_actions_[c] >= k) {
          return fail(values + ": " + choice(c) + " has action " +
                      std::to_string(choice_actions_[c]) + ", but \"#choice-actions\" is " +
                      std::to_string(k));
        }
      }
    }
    const std::string mapping = "actions/choices/string-mapping.bin";
    const std::string strings = "actions/choices/strings.bin";
    const std::string* text = entry(strings);
    if (entry(mapping) == nullptr) {
      if (text != nullptr) return fail(strings + ": present without " + mapping);
      return true;  // no names: every choice is unlabelled
    }
    if (text == nullptr) return fail(strings + ": absent, but " + mapping + " maps into it");
    std::vector<std::uint32_t> offsets;
    if (text->size() >= UINT32_MAX) return fail(strings + ": too large");
    if (!read_csr(mapping, k, text->size(), "actions", "bytes of strings.bin", offsets))
      return false;
    action_names_.resize(k);
    for (std::uint64_t a = 0; a < k; ++a) {
      action_names_[a] = text->substr(offsets[a], offsets[a + 1] - offsets[a]);
      if (!is_umb_name(action_names_[a])) {
        return fail(strings + ": the name of action " + std::to_string(a) +
                    " is not UTF-8 text without control characters");
      }
    }
    return true;
  }

  [[nodiscard]] std::string action_name(std::uint64_t c, std::uint32_t j) const {
    if (index_.markov_chain) return unlabelled_action_name(0);
    if (choice_actions_.empty() || action_names_.empty()) return unlabelled_action_name(j);
    const std::string& name = action_names_[choice_actions_[c]];
    return name.empty() ? unlabelled_action_name(j) : name;
  }

  ActionIndex action_index(const std::string& name) {
    const auto [it, inserted] =
        action_indices_.try_emplace(name, static_cast<ActionIndex>(model_.actions.size()));
    if (inserted) model_.actions.push_back(name);
    return it->second;
  }

  // Each choice's distribution, checked to be one.
  bool read_choices() {
    const std::string name = "branch-to-probability.bin";
    for (StateIndex s = 0; s < index_.num_states; ++s) {
      for (std::uint32_t c = state_choices_[s]; c < state_choices_[s + 1]; ++c) {
        const std::uint32_t j = c - state_choices_[s];
        collector_.begin(s, action_index(action_name(c, j)), 0, j);
        if (choice_branches_[c] == choice_branches_[c + 1])
          return fail("choice-to-branches.bin: " + choice(c) + " has no branches");
        ExactSum sum;
        sum.reset();
        for (std::uint32_t b = choice_branches_[c]; b < choice_branches_[c + 1]; ++b) {
          if (sgn(values_.pool()[probabilities_[b]]) <= 0) {
            return fail(name + ": " + branch(b) + " has the probability " +
                        describe(values_.pool()[probabilities_[b]]) + "; it must be positive");
          }
          collector_.add(targets_[b], probabilities_[b]);
          sum.add(probabilities_[b], values_);
        }
        if (sum.compare_to_one() == 0) continue;
        const Rational total = sum.value();
        if (options_.tolerance && abs(total - 1) <= *options_.tolerance) continue;
        return fail(name + ": the probabilities of " + choice(c) + " sum to " + describe(total) +
                    ", not 1");
      }
    }
    return true;
  }

  bool read_labels() {
    std::vector<std::string> names;
    std::vector<std::pair<StateIndex, std::uint32_t>> pairs;
    for (const UmbAnnotation& ap : index_.aps) {
      const std::string name = "annotations/aps/" + ap.id + "/states/values.bin";
      if (ap.name.find('"') != std::string::npos) {
        return fail("index.json: atomic proposition '" + ap.name +
                    "' holds a '\"', which no label can");
      }
      std::vector<StateIndex> states;
      if (!read_bitset(name, index_.num_states, states)) return false;
      if (ap.name == "init") {  // the initial states' label, which the bitset gives
        if (states != initial_) {
          return fail(name +
                      ": the atomic proposition \"init\" differs from the initial states "
                      "(state-is-initial.bin)");
        }
        continue;
      }
      for (const StateIndex s : states)
        pairs.emplace_back(s, static_cast<std::uint32_t>(names.size()));
      names.push_back(ap.name);
    }
    const auto init = static_cast<std::uint32_t>(names.size());
    names.emplace_back("init");
    for (const StateIndex s : initial_)
      pairs.emplace_back(s, init);
    model::StateLabelsBuilder builder(std::move(names));
    for (const auto& [state, label] : pairs)
      builder.add(state, label);
    model_.labels = builder.finish(static_cast<std::uint32_t>(index_.num_states));
    model_.states.initial = initial_;
    return true;
  }

  // --- Rewards ---------------------------------------------------------------------------

  bool read_rewards() {
    for (const UmbAnnotation& reward : index_.rewards) {
      const std::string folder = "annotations/rewards/" + reward.id + "/";
      std::vector<ValueId> state;
      std::vector<ValueId> by_choice;
      std::vector<ValueId> by_branch;
      if (reward.states && !read_numbers(folder + "states/values.bin", reward.type,
                                         index_.num_states, "the reward", state)) {
        return false;
      }
      if (reward.choices && !read_numbers(folder + "choices/values.bin", reward.type,
                                          index_.num_choices, "the reward", by_choice)) {
        return false;
      }
      if (reward.branches && !read_numbers(folder + "branches/values.bin", reward.type,
                                           index_.num_branches, "the reward", by_branch)) {
        return false;
      }
      if (state.empty()) state.assign(index_.num_states, RationalPool::kZero);
      state_rewards_.push_back(std::move(state));
      choice_rewards_.emplace_back();
      if (!merge_choice_rewards(folder, by_choice, by_branch, choice_rewards_.back())) return false;
    }
    return true;
  }

  // R(choice) = its choice reward + the reward its branches share (PRISM's transition
  // rewards of an MDP belong to the choice; branches that disagree cannot be kept).
  bool merge_choice_rewards(const std::string& folder, const std::vector<ValueId>& by_choice,
                            const std::vector<ValueId>& by_branch, std::vector<ValueId>& merged) {
    if (by_choice.empty() && by_branch.empty()) return true;
    merged.assign(index_.num_choices, RationalPool::kZero);
    for (std::uint64_t c = 0; c < index_.num_choices; ++c) {
      ValueId value = by_choice.empty() ? RationalPool::kZero : by_choice[c];
      if (!by_branch.empty()) {
        const ValueId shared = by_branch[choice_branches_[c]];
        for (std::uint32_t b = choice_branches_[c]; b < choice_branches_[c + 1]; ++b) {
          if (by_branch[b] != shared) {
            return fail(folder + "branches/values.bin: the branches of " + choice(c) +
                        " have different rewards; oasis keeps one reward per choice");
          }
        }
        if (shared != RationalPool::kZero)
          value = values_.intern(values_.pool()[value] + values_.pool()[shared]);
      }
      merged[c] = value;
    }
    return true;
  }

  // --- The model -------------------------------------------------------------------------

  bool build() {
    const auto n = static_cast<std::uint32_t>(index_.num_states);
    const auto k = static_cast<std::uint32_t>(model_.actions.size());
    if (std::uint64_t{n} * k >= UINT32_MAX) {
      return fail(std::to_string(n) + " states and " + std::to_string(k) +
                  " actions make more than 2^32 state-action pairs");
    }
    std::vector<DistributionCollector::Duplicate> duplicates;
    std::optional<model::TransitionMatrix> matrix =
        collector_.finish(n, k, model_.values, duplicates);
    if (!duplicates.empty()) {
      const DistributionCollector::Duplicate& duplicate = duplicates.front();
      return fail("state " + std::to_string(collector_.source(duplicate.first)) +
                  " has two choices named '" + model_.actions[collector_.action(duplicate.first)] +
                  "' (choices " + std::to_string(collector_.payload(duplicate.first)) + " and " +
                  std::to_string(collector_.payload(duplicate.second)) +
                  "); an MDP allows one per action");
    }
    if (!matrix) return fail("the transitions cannot be built");
    model_.name = std::filesystem::path(path_).stem().string();
    model_.type = index_.markov_chain ? model::ModelType::kDtmc : model::ModelType::kMdp;
    model_.states.size = n;
    build_contexts(std::make_shared<const model::TransitionMatrix>(std::move(*matrix)));
    return true;
  }

  // The states' valuations, where the file has them in a form the model keeps; else they are
  // read past with a warning (they name states, nothing depends on them).
  bool read_valuations() {
    std::string why = index_.valuations_skipped;
    if (index_.valuations) {
      const std::string name = "valuations/states/valuations.bin";
      const std::string* bytes = entry(name);
      const std::uint64_t stride = index_.valuations->bits / 8;
      if (entry("valuations/states/valuation-to-class.bin") != nullptr) {
        why = "valuations/states/valuation-to-class.bin gives states several classes";
      } else if (bytes == nullptr) {
        why = name + " is absent";
      } else if (bytes->size() % stride != 0 || bytes->size() / stride != index_.num_states) {
        why = name + " holds " + std::to_string(bytes->size()) + " bytes, not " +
              std::to_string(index_.num_states) + " valuations of " + std::to_string(stride);
      } else if (decode_umb_valuations(*index_.valuations, *bytes, index_.num_states,
                                       model_.states.valuations, why)) {
        for (const UmbField& field : index_.valuations->fields) {
          if (field.kind != UmbField::Kind::kPadding) model_.states.variables.push_back(field.name);
        }
        return true;
      }
      model_.states.valuations.clear();
    }
    if (!why.empty())
      diagnostics_.file_warning(path_, "the state valuations are read past: " + why);
    return true;
  }

  void build_contexts(const std::shared_ptr<const model::TransitionMatrix>& matrix) {
    if (index_.rewards.empty()) {
      model::Context context;
      context.name = "default";
      context.transitions = matrix;
      context.rewards.state.assign(index_.num_states, RationalPool::kZero);
      model_.contexts.push_back(std::move(context));
      return;
    }
    const std::size_t k = model_.actions.size();
    for (std::size_t r = 0; r < index_.rewards.size(); ++r) {
      model::Context context;
      context.name = index_.rewards[r].name;
      context.transitions = matrix;
      context.rewards.state = std::move(state_rewards_[r]);
      const std::vector<ValueId>& by_choice = choice_rewards_[r];
      if (!by_choice.empty()) {
        context.rewards.choice.assign(index_.num_states * k, RationalPool::kZero);
        for (std::uint32_t d = 0; d < collector_.size(); ++d) {
          const std::uint64_t c = state_choices_[collector_.source(d)] + collector_.payload(d);
          context.rewards.choice[collector_.source(d) * k + collector_.action(d)] = by_choice[c];
        }
      }
      model_.contexts.push_back(std::move(context));
    }
  }

  DiagnosticEngine& diagnostics_;
  const ReadOptions& options_;
  model::ExplicitModel& model_;
  ValueCache values_;
  std::string path_;
  std::string_view bytes_;
  std::map<std::string, std::string, std::less<>> entries_;
  UmbIndex index_;
  std::vector<std::uint32_t> state_choices_;    // CSR, #states + 1
  std::vector<std::uint32_t> choice_branches_;  // CSR, #choices + 1
  std::vector<StateIndex> targets_;             // per branch
  std::vector<ValueId> probabilities_;          // per branch
  std::vector<StateIndex> initial_;
  std::vector<std::uint32_t> choice_actions_;  // per choice (MDPs with actions)
  std::vector<std::string> action_names_;      // per action index (when the file names them)
  std::unordered_map<std::string, ActionIndex> action_indices_;
  std::unordered_map<std::uint64_t, ValueId> doubles_;  // by bit pattern
  std::vector<std::uint8_t> judged_;                    // by ValueId: checked once
  DistributionCollector collector_;
  std::vector<std::vector<ValueId>> state_rewards_;   // per reward annotation, per state
  std::vector<std::vector<ValueId>> choice_rewards_;  // per reward annotation, per choice
};

}  // namespace

std::optional<model::ExplicitModel> read_umb(FileId file, DiagnosticEngine& diagnostics,
                                             const ReadOptions& options) {
  model::ExplicitModel model;
  if (!UmbReader(file, diagnostics, options, model).read()) return std::nullopt;
  return model;
}

}  // namespace oasis::formats
