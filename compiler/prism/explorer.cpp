#include "prism/explorer.hpp"

#include <algorithm>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "formats/explicit_reader.hpp"
#include "model/state_store.hpp"
#include "model/transition_stream.hpp"
#include "model/valuation_text.hpp"
#include "support/double_range.hpp"
#include "support/huge_page_growth.hpp"
#include "support/text.hpp"

namespace oasis::prism {
namespace {

using model::Expression;
using model::StateIndex;

// Raised after a diagnostic has been reported; ends exploration.
struct ExplorationFailed {};

// More choices than this in one state means a synchronisation whose combinations explode.
constexpr std::size_t kMaxChoicesPerState = 100'000;
// Nor more outcomes than this in one choice (the product of its commands' updates).
constexpr std::uint64_t kMaxOutcomesPerChoice = 1'000'000;
// Nor more than this over all of a state's choices, which are held together (work_out()).
constexpr std::size_t kMaxOutcomesPerState = 10'000'000;
// `init ... endinit` is solved by trying every valuation; past this many it is refused.
constexpr std::uint64_t kMaxInitCandidates = std::uint64_t{1} << 24;

// One choice of a state: the commands that take part (one, or one per synchronising module),
// choice_commands_[first .. first + count).
struct Choice {
  std::optional<std::uint32_t> action;
  std::uint32_t first = 0;
  std::uint32_t count = 0;
};

class Explorer {
 public:
  Explorer(const Program& program, DiagnosticEngine& diagnostics, const ExploreOptions& options)
      : program_(program),
        diagnostics_(diagnostics),
        options_(options),
        store_(program.variables),
        valuation_(program.variables.size()),
        key_(store_.words_per_state()),
        action_rewards_(program.rewards.size()),
        labelled_ids_(program.actions.size()) {}

  std::optional<model::ExplicitModel> run() {
    try {
      prepare_probabilities();
      add_initial_states();
      explore_all();
      return build_model();
    } catch (const ExplorationFailed&) {
      return std::nullopt;
    }
  }

 private:
  // --- Initial states ------------------------------------------------------------------------

  // Indexes the commands once: the unlabelled ones; per action, the modules that take part
  // and their commands of it; the pool ids of constant probabilities.
  void prepare_probabilities() {
    by_action_.resize(program_.actions.size());
    for (const Module& module : program_.modules) {
      for (std::uint32_t a = 0; a < program_.actions.size(); ++a) {
        if (module.alphabet[a]) by_action_[a].emplace_back();
      }
      for (const Command& command : module.commands) {
        if (command.action) {
          by_action_[*command.action].back().push_back(&command);
        } else {
          unlabelled_.push_back(&command);
        }
        if (first_update_.size() <= command.serial) first_update_.resize(command.serial + 1);
        first_update_[command.serial] = static_cast<std::uint32_t>(probability_ids_.size());
        for (const Update& update : command.updates) {
          probability_ids_.push_back(update.probability.is_constant()
                                         ? values_.intern(update.probability.constant)
                                         : kStateDependent);
        }
      }
    }
    participants_.resize(program_.modules.size());
    pick_.assign(program_.modules.size(), 0);
    for (const RewardStructure& structure : program_.rewards) {
      const bool any =
          std::any_of(structure.items.begin(), structure.items.end(),
                      [](const RewardItem& item) { return item.kind != RewardItem::Kind::State; });
      action_items_.push_back(any);
      has_action_rewards_ = has_action_rewards_ || any;
    }
  }

  void add_initial_states() {
    if (!program_.init_predicate) {
      for (std::size_t v = 0; v < program_.variables.size(); ++v)
        valuation_[v] = program_.variables[v].init;
      initial_.push_back(intern(valuation_, program_.range));
      return;
    }
    std::uint64_t candidates = 1;
    for (const model::DiscreteVariable& var : program_.variables) {
      const auto width = static_cast<std::uint64_t>(var.high - var.low) + 1;
      if (width > kMaxInitCandidates || candidates * width > kMaxInitCandidates) {
        diagnostics_.error(program_.init_predicate->range,
                           "'init ... endinit' would try more than " +
                               std::to_string(kMaxInitCandidates) +
                               " valuations; give each variable an init instead");
        throw ExplorationFailed{};
      }
      candidates *= width;
    }
    for (std::size_t v = 0; v < program_.variables.size(); ++v)
      valuation_[v] = program_.variables[v].low;
    for (std::uint64_t i = 0; i < candidates; ++i) {
      if (evaluate([&] { return model::evaluate_bool(*program_.init_predicate, valuation_); }))
        initial_.push_back(intern(valuation_, program_.init_predicate->range));
      next_valuation();
    }
    if (initial_.empty()) {
      diagnostics_.error(program_.init_predicate->range,
                         "no valuation satisfies the initial states' predicate");
      throw ExplorationFailed{};
    }
  }

  // Counts through every valuation, the last variable fastest.
  void next_valuation() {
    for (std::size_t v = program_.variables.size(); v-- > 0;) {
      if (valuation_[v] < program_.variables[v].high) {
        ++valuation_[v];
        return;
      }
      valuation_[v] = program_.variables[v].low;
    }
  }

  StateIndex intern(model::Valuation valuation, SourceRange cause) {
    store_.pack(valuation, key_);
    return intern_key(key_, cause);
  }

  StateIndex intern_key(std::span<const std::uint64_t> key, SourceRange cause) {
    const auto [index, inserted] = store_.insert(key);
    if (inserted && store_.size() > options_.max_states) {
      diagnostics_.error(cause, "exploration passed the limit of " +
                                    std::to_string(options_.max_states) +
                                    " states (raise it with --max-states)");
      throw ExplorationFailed{};
    }
    return index;
  }

  // --- States, in batches --------------------------------------------------------------------

  // States are explored in batches: the choices and outcomes of a few states are worked out
  // first (work_out) and their successors looked up after, all together (intern_batch). A new
  // state's slot in the store is at random in a large table, a miss to memory; prefetching
  // the slots of a whole batch lets those misses overlap. Successors are interned in the
  // order found, so states are numbered as one at a time would number them, and values are
  // interned in the same order too. A batch grows only while its lookups and distributions
  // cannot pass a limit, so that every error is the one that one state at a time reports.
  static constexpr std::uint32_t kBatchStates = 8;

  // A state of the batch: its choices end at choices_[choices_end], its outcomes start at
  // row_[row_begin]; its action rewards are in reward_ids_ from rewards_begin when known.
  struct Worked {
    StateIndex state;
    std::uint32_t choices_end;
    std::size_t row_begin;
    std::size_t rewards_begin;
    bool rewards_known;
  };

  void explore_all() {
    for (StateIndex s = 0; s < store_.size();) {
      start_batch();
      StateIndex end = s;
      bool safe = true;
      do {
        work_out(end);
        safe = batch_cannot_fail();
        // Action rewards may fail to evaluate: only where the lookups cannot fail are they
        // evaluated before them (and interned, in the order one at a time would intern them).
        if (safe) evaluate_action_rewards(batch_.back());
        ++end;
      } while (safe && end < store_.size() && end - s < kBatchStates);
      intern_batch();
      std::uint32_t choices_begin = 0;
      for (const Worked& worked : batch_) {
        emit_state(worked, choices_begin);
        choices_begin = worked.choices_end;
        if (options_.progress && (worked.state & 0xFFFFU) == 0xFFFFU)
          options_.progress(store_.size(), worked.state + 1);
      }
      s = end;
    }
  }

  void start_batch() {
    batch_.clear();
    choices_.clear();
    choice_commands_.clear();
    choice_ends_.clear();
    row_.clear();
    pending_.clear();
    pending_keys_.clear();
    reward_ids_.clear();
  }

  // Whether interning the batch's successors, even if each were new, and adding its
  // distributions keep within the limits that intern_key() and found_distribution() check.
  [[nodiscard]] bool batch_cannot_fail() const {
    const std::uint64_t most_states = std::uint64_t{store_.size()} + pending_.size();
    const std::uint64_t most_edges =
        edges_found_ + row_.size() + batch_.size();  // a deadlock's self-loop
    return most_states <= options_.max_states && most_edges < UINT32_MAX - 1;
  }

  // The choices of state s and their outcomes, appended to the batch; no lookups yet.
  void work_out(StateIndex s) {
    store_.unpack(s, valuation_);
    current_ = s;
    const auto choices_begin = static_cast<std::uint32_t>(choices_.size());
    const std::size_t row_begin = row_.size();
    collect_choices(choices_begin);
    for (std::uint32_t c = choices_begin; c < choices_.size(); ++c) {
      start_outcomes(choices_[c]);
      choice_ends_.push_back(row_.size());
      if (row_.size() - row_begin > kMaxOutcomesPerState) {
        diagnostics_.error(program_.range, "state " + state_text() + " has more than " +
                                               std::to_string(kMaxOutcomesPerState) +
                                               " outcomes over all its choices");
        throw ExplorationFailed{};
      }
    }
    const auto count = static_cast<std::uint32_t>(choices_.size()) - choices_begin;
    // A dtmc's one distribution is the average of its enabled choices.
    if (program_.type == ModelType::Dtmc && count > 1) {
      const Rational share(1, static_cast<unsigned long>(count));
      for (std::size_t o = row_begin; o < row_.size(); ++o)
        row_[o].second = values_.intern(values_[row_[o].second] * share);
    }
    batch_.push_back({s, static_cast<std::uint32_t>(choices_.size()), row_begin, 0, false});
  }

  // Every successor of the batch still to look up, in the order found.
  void intern_batch() {
    const std::size_t words = store_.words_per_state();
    for (std::size_t p = 0; p < pending_.size(); ++p) {
      const std::span<const std::uint64_t> key(pending_keys_.data() + p * words, words);
      row_[pending_[p].position].first = intern_key(key, pending_[p].cause);
    }
  }

  // The distributions of a worked-out state whose successors are all interned.
  void emit_state(const Worked& worked, std::uint32_t choices_begin) {
    const StateIndex s = worked.state;
    if (choices_begin == worked.choices_end) {
      deadlocks_.push_back(s);
      const model::ActionIndex action = action_id(std::nullopt, 0);
      found_distribution(s, action, 1);
      record_no_action_rewards();  // the self-loop PRISM adds earns nothing
      if (begin_in_stream(s, action)) stream_.add(s, RationalPool::kOne);
      return;
    }
    if (program_.type == ModelType::Dtmc) {
      const model::ActionIndex action = action_id(std::nullopt, 0);
      const std::size_t last = choice_ends_[worked.choices_end - 1];
      found_distribution(s, action, last - worked.row_begin);
      record_action_rewards(worked, 0, std::nullopt, choices_begin);
      stream_row(s, action, worked.row_begin, last);
      return;
    }
    state_distributions_.clear();
    // The choice's place among the state's choices of its label (or the unlabelled ones),
    // which collect_choices() lists together.
    std::uint32_t position = 0;
    for (std::uint32_t c = choices_begin; c < worked.choices_end; ++c) {
      const Choice& choice = choices_[c];
      position = c > choices_begin && choices_[c - 1].action == choice.action ? position + 1 : 0;
      const model::ActionIndex action = action_id(choice.action, position);
      const std::size_t first = c == choices_begin ? worked.row_begin : choice_ends_[c - 1];
      found_distribution(s, action, choice_ends_[c] - first);
      record_action_rewards(worked, c - choices_begin, choice.action, choices_begin);
      state_distributions_.push_back({action, first, choice_ends_[c]});
    }
    // The stream takes a state's choices in action order. Actions are numbered as they are
    // found, so a state may find its choices in another order (an action first found later).
    std::sort(
        state_distributions_.begin(), state_distributions_.end(),
        [](const FoundDistribution& x, const FoundDistribution& y) { return x.action < y.action; });
    for (const FoundDistribution& found : state_distributions_)
      stream_row(s, found.action, found.first, found.last);
  }

  // Outcomes [first, last) of row_ as the distribution of (s, action). Sorted here, where
  // they are in the cache; the stream merges a repeated target.
  void stream_row(StateIndex s, model::ActionIndex action, std::size_t first, std::size_t last) {
    if (!begin_in_stream(s, action)) return;
    model::sort_by_target(std::span(row_).subspan(first, last - first));
    for (std::size_t o = first; o < last; ++o)
      stream_.add(row_[o].first, row_[o].second);
  }

  // The enabled choices of the state in valuation_, appended to choices_ from `first`:
  // unlabelled ones first, then each action's combinations.
  void collect_choices(std::uint32_t first) {
    for (const Command* command : unlabelled_) {
      if (!enabled(*command)) continue;
      choices_.push_back({std::nullopt, static_cast<std::uint32_t>(choice_commands_.size()), 1});
      choice_commands_.push_back(command);
    }
    for (std::uint32_t a = 0; a < program_.actions.size(); ++a)
      collect_synchronised(a, first);
    if (choices_.size() - first > kMaxChoicesPerState) {
      diagnostics_.error(program_.range, "state " + state_text() + " has more than " +
                                             std::to_string(kMaxChoicesPerState) + " choices");
      throw ExplorationFailed{};
    }
  }

  void collect_synchronised(std::uint32_t a, std::uint32_t first) {
    // The enabled `a` commands of each module that has `a`; none in one of them blocks `a`.
    const auto& modules = by_action_[a];
    for (std::size_t m = 0; m < modules.size(); ++m) {
      participants_[m].clear();
      for (const Command* command : modules[m]) {
        if (enabled(*command)) participants_[m].push_back(command);
      }
      if (participants_[m].empty()) return;
    }
    // Every combination, the first module's command varying slowest.
    const std::size_t n = modules.size();
    // pick_ is all zeros: the odometer below leaves it so whenever it stops (clearing it here,
    // a call to memset, made the reads that follow wait for its stores).
    for (;;) {
      choices_.push_back(
          {a, static_cast<std::uint32_t>(choice_commands_.size()), static_cast<std::uint32_t>(n)});
      for (std::size_t m = 0; m < n; ++m)
        choice_commands_.push_back(participants_[m][pick_[m]]);
      if (choices_.size() - first > kMaxChoicesPerState) {  // reported by the caller
        std::fill(pick_.begin(), pick_.end(), 0);
        return;
      }
      std::size_t m = n;
      while (m > 0 && ++pick_[m - 1] == participants_[m - 1].size())
        pick_[--m] = 0;
      if (m == 0) return;
    }
  }

  bool enabled(const Command& command) {
    return evaluate([&] { return model::evaluate_bool(command.guard, valuation_); });
  }

  // The packed key of the successor under construction after i commands (stack_).
  std::span<std::uint64_t> stacked_key(std::size_t i) {
    const std::size_t words = store_.words_per_state();
    return {stack_.data() + i * words, words};
  }

  // The outcomes of choice.commands[i..], appended to row_: stacked_key(i) is the successor
  // as the earlier commands' updates left it, reached with `probability`. Every update reads
  // the source state, as in PRISM.
  void outcomes(const Choice& choice, std::size_t i, ValueId probability) {
    if (i == choice.count) {
      // A self-loop (`true`, an update that changes nothing) needs no lookup in the store;
      // another successor is looked up later (intern_batch()), its slot fetched now.
      const std::span<const std::uint64_t> key = stacked_key(i);
      if (store_.is_key_of(current_, key)) {
        row_.emplace_back(current_, probability);
        return;
      }
      store_.prefetch(key);
      pending_keys_.insert(pending_keys_.end(), key.begin(), key.end());
      pending_.push_back({row_.size(), choice_commands_[choice.first]->range});
      row_.emplace_back(0, probability);
      return;
    }
    const Command& command = *choice_commands_[choice.first + i];
    // Sums only where a probability depends on the state: the checker has summed the others.
    const bool check_sum = !command.constant_probabilities;
    if (check_sum) sums_[i] = 0;
    const ValueId* ids = probability_ids_.data() + first_update_[command.serial];
    for (const Update& update : command.updates) {
      const ValueId id = *ids++;
      const ValueId p = id == kStateDependent ? state_probability(update) : id;
      if (check_sum) sums_[i] += values_[p];
      if (p == RationalPool::kZero) continue;
      const std::span<std::uint64_t> next = stacked_key(i + 1);
      const std::span<const std::uint64_t> before = stacked_key(i);
      std::copy(before.begin(), before.end(), next.begin());
      for (const model::Update& assignment : update.assignments)
        apply(assignment, next);
      const ValueId combined =
          probability == RationalPool::kOne ? p : values_.intern(values_[probability] * values_[p]);
      outcomes(choice, i + 1, combined);
    }
    if (check_sum && sums_[i] != 1) {
      diagnostics_.error(command.range, "in state " + state_text() + " the probabilities sum to " +
                                            describe(sums_[i]) + ", not 1");
      throw ExplorationFailed{};
    }
  }

  void start_outcomes(const Choice& choice) {
    check_outcome_count(choice);
    const std::size_t words = store_.words_per_state();
    if (sums_.size() < choice.count + 1) {
      stack_.resize((choice.count + 1) * words);
      sums_.resize(choice.count + 1);
    }
    const std::span<const std::uint64_t> current = store_.key_of(current_);
    std::copy(current.begin(), current.end(), stack_.begin());
    outcomes(choice, 0, RationalPool::kOne);
  }

  // The outcomes of a synchronised choice multiply: refuse a product that would not end.
  void check_outcome_count(const Choice& choice) {
    std::uint64_t outcomes = 1;
    for (std::uint32_t i = 0; i < choice.count; ++i) {
      outcomes *= std::max<std::size_t>(1, choice_commands_[choice.first + i]->updates.size());
      if (outcomes > kMaxOutcomesPerChoice) {
        diagnostics_.error(choice_commands_[choice.first]->range,
                           "in state " + state_text() + " the synchronised commands of action " +
                               quoted(program_.actions.at(*choice.action)) + " have more than " +
                               std::to_string(kMaxOutcomesPerChoice) + " combined outcomes");
        throw ExplorationFailed{};
      }
    }
  }

  // A probability that depends on the state, evaluated and checked in this one.
  ValueId state_probability(const Update& update) {
    const Rational value =
        evaluate([&] { return model::evaluate_number(update.probability, valuation_); });
    if (value < 0 || value > 1) {
      diagnostics_.error(update.probability.range, "probability " + describe(value) + " in state " +
                                                       state_text() + " is not in [0, 1]");
      throw ExplorationFailed{};
    }
    return values_.intern(value);
  }

  // Sets the updated variable in `successor`, a packed key.
  void apply(const model::Update& update, std::span<std::uint64_t> successor) {
    const std::int64_t value =
        evaluate([&] { return model::evaluate_int(update.value, valuation_); });
    const model::DiscreteVariable& variable = program_.variables[update.variable];
    if (value < variable.low || value > variable.high) {
      diagnostics_.error(update.range,
                         model::range_violation(variable, value) + ", in state " + state_text());
      throw ExplorationFailed{};
    }
    store_.set(successor, update.variable, value);
  }

  template <typename Evaluate>
  auto evaluate(Evaluate&& run) -> decltype(run()) {
    try {
      return run();
    } catch (const model::EvaluationError& error) {
      diagnostics_.error(error.where, std::string(error.what()) + " in state " + state_text());
      throw ExplorationFailed{};
    }
  }

  // --- Actions and distributions -------------------------------------------------------------

  // The action of the `position`-th choice labelled `label` (or unlabelled) in a state.
  model::ActionIndex action_id(std::optional<std::uint32_t> label, std::uint32_t position) {
    auto& ids = label ? labelled_ids_[*label] : unlabelled_ids_;
    if (position < ids.size()) return ids[position];
    std::string name;
    if (!label || program_.type == ModelType::Dtmc) {
      name = formats::unlabelled_action_name(position);
    } else {
      name = program_.actions[*label];
      if (position > 0) name += "[" + std::to_string(position) + "]";
    }
    while (ids.size() <= position) {
      ids.push_back(static_cast<model::ActionIndex>(action_names_.size()));
      action_names_.push_back(ids.size() - 1 == position ? name : std::string());
    }
    return ids[position];
  }

  // Counts a distribution of (s, action), in the order the state's choices are found (its
  // action rewards are recorded in that order too); refuses one past 2^32 edges.
  void found_distribution(StateIndex s, model::ActionIndex action, std::size_t edges) {
    if (edges_found_ >= UINT32_MAX - 1) {
      diagnostics_.error(program_.range, "the model has more than 2^32 transitions");
      throw ExplorationFailed{};
    }
    ++num_distributions_;
    edges_found_ += edges;
    if (has_action_rewards_) distribution_choices_.emplace_back(s, action);
  }

  // Starts the distribution of (s, action) in the stream, whose choice indices count the
  // actions found so far. A new action re-spaces the choices the stream holds (a pass over
  // them): once it holds many, its count runs ahead of the actions found, doubling, so that
  // the passes stay few; build_model() gives it the true count. False when the choice index
  // passes 32 bits: build_model() then reports more than 2^32 state-action pairs.
  bool begin_in_stream(StateIndex s, model::ActionIndex action) {
    const auto found = static_cast<std::uint32_t>(action_names_.size());
    if (action >= stream_.num_actions()) {
      const bool large = std::uint64_t{s} * stream_.num_actions() > kExactActionCountChoices;
      stream_.set_num_actions(large ? std::max(found, 2 * stream_.num_actions()) : found);
    }
    std::uint64_t choice = std::uint64_t{s} * stream_.num_actions() + action;
    if (choice >= UINT32_MAX && stream_.num_actions() > found) {
      stream_.set_num_actions(found);
      choice = std::uint64_t{s} * found + action;
    }
    if (choice >= UINT32_MAX) return false;
    stream_.begin(static_cast<model::ChoiceIndex>(choice));
    return true;
  }

  // --- Rewards -------------------------------------------------------------------------------

  // The action rewards of the state just worked out (valuation_), per distribution and
  // reward structure, into reward_ids_: the items of its label whose guard holds; in a dtmc
  // the average over the state's choices.
  void evaluate_action_rewards(Worked& worked) {
    if (!has_action_rewards_) return;
    const std::uint32_t first = batch_.size() > 1 ? batch_[batch_.size() - 2].choices_end : 0;
    worked.rewards_begin = reward_ids_.size();
    worked.rewards_known = true;
    if (first == worked.choices_end) return;  // a deadlock earns nothing
    if (program_.type == ModelType::Dtmc) {
      append_action_rewards(std::nullopt, first, worked.choices_end);
      return;
    }
    for (std::uint32_t c = first; c < worked.choices_end; ++c)
      append_action_rewards(choices_[c].action, first, worked.choices_end);
  }

  // One distribution's action reward per structure; a dtmc's (no label) averages choices
  // [first, last).
  void append_action_rewards(std::optional<std::uint32_t> label, std::uint32_t first,
                             std::uint32_t last) {
    const bool mixture = program_.type == ModelType::Dtmc;
    for (const RewardStructure& structure : program_.rewards) {
      Rational total = 0;
      for (const RewardItem& item : structure.items) {
        if (item.kind == RewardItem::Kind::State) continue;
        if (!mixture) {
          total += item_reward(item, label);
          continue;
        }
        const Rational share(1, static_cast<unsigned long>(last - first));
        for (std::uint32_t c = first; c < last; ++c)
          total += item_reward(item, choices_[c].action) * share;
      }
      reward_ids_.push_back(total != 0 ? values_.intern(total) : RationalPool::kZero);
    }
  }

  // The action rewards of the distribution just begun, the `index`-th of its state: from
  // reward_ids_ when evaluate_action_rewards() has found them, else evaluated now (the state
  // is then the batch's last, still in valuation_).
  void record_action_rewards(Worked worked, std::uint32_t index, std::optional<std::uint32_t> label,
                             std::uint32_t choices_begin) {
    if (!has_action_rewards_) return;
    if (!worked.rewards_known) {
      worked.rewards_begin = reward_ids_.size();
      if (program_.type == ModelType::Dtmc) {
        append_action_rewards(std::nullopt, choices_begin, worked.choices_end);
      } else {
        append_action_rewards(label, choices_begin, worked.choices_end);
      }
      index = 0;
    }
    const std::size_t at = worked.rewards_begin + std::size_t{index} * program_.rewards.size();
    for (std::size_t r = 0; r < program_.rewards.size(); ++r) {
      if (!action_items_[r]) continue;
      action_rewards_[r].resize(num_distributions_, RationalPool::kZero);
      action_rewards_[r].back() = reward_ids_[at + r];
    }
  }

  void record_no_action_rewards() {
    for (std::vector<ValueId>& rewards : action_rewards_) {
      if (!rewards.empty()) rewards.resize(num_distributions_, RationalPool::kZero);
    }
  }

  Rational item_reward(const RewardItem& item, std::optional<std::uint32_t> label) {
    const bool matches =
        item.kind == RewardItem::Kind::Unlabelled ? !label.has_value() : label == item.action;
    if (!matches || !evaluate([&] { return model::evaluate_bool(item.guard, valuation_); }))
      return 0;
    return evaluate([&] { return model::evaluate_number(item.value, valuation_); });
  }

  // --- The model -----------------------------------------------------------------------------

  model::ExplicitModel build_model() {
    store_.end_lookups();
    const std::uint32_t n = store_.size();
    const auto num_actions = static_cast<std::uint32_t>(action_names_.size());
    if (std::uint64_t{n} * num_actions >= UINT32_MAX) {
      diagnostics_.error(program_.range, "model has more than 2^32 state-action pairs (" +
                                             std::to_string(n) + " states x " +
                                             std::to_string(num_actions) + " actions)");
      throw ExplorationFailed{};
    }
    model::ExplicitModel model;
    model.name = program_.name;
    model.type =
        program_.type == ModelType::Dtmc ? model::ModelType::kDtmc : model::ModelType::kMdp;
    model.actions = action_names_;
    fill_state_space(model.states);
    stream_.set_num_actions(num_actions);
    auto transitions = std::make_shared<const model::TransitionMatrix>(stream_.finish(n, values_));
    if (program_.rewards.empty())
      model.contexts.push_back({"default", transitions, zero_rewards(n)});
    for (std::size_t r = 0; r < program_.rewards.size(); ++r) {
      model.contexts.push_back({program_.rewards[r].name, transitions, rewards(r, n, num_actions)});
    }
    model.labels = labels(n);
    model.values = std::move(values_);
    return model;
  }

  void fill_state_space(model::StateSpace& space) {
    space.size = store_.size();
    space.initial = initial_;
    const std::size_t width = program_.variables.size();
    for (const model::DiscreteVariable& var : program_.variables)
      space.variables.push_back(var.name);
    reserve_huge(space.valuations, std::size_t{space.size} * width);
    space.valuations.resize(std::size_t{space.size} * width);
    for (StateIndex s = 0; s < space.size; ++s)
      store_.unpack(s, std::span(space.valuations).subspan(std::size_t{s} * width, width));
  }

  static model::RewardTable zero_rewards(std::uint32_t n) {
    model::RewardTable table;
    table.state.assign(n, RationalPool::kZero);
    return table;
  }

  model::RewardTable rewards(std::size_t r, std::uint32_t n, std::uint32_t num_actions) {
    model::RewardTable table = zero_rewards(n);
    const RewardStructure& structure = program_.rewards[r];
    for (StateIndex s = 0; s < n; ++s) {
      store_.unpack(s, valuation_);
      Rational total = 0;
      for (const RewardItem& item : structure.items) {
        if (item.kind != RewardItem::Kind::State) continue;
        if (evaluate([&] { return model::evaluate_bool(item.guard, valuation_); }))
          total += evaluate([&] { return model::evaluate_number(item.value, valuation_); });
      }
      if (total != 0) table.state[s] = checked_value(total, structure.range);
    }
    const std::vector<ValueId>& per_distribution = action_rewards_[r];
    if (per_distribution.empty()) return table;
    table.choice.assign(std::size_t{n} * num_actions, RationalPool::kZero);
    for (std::uint32_t d = 0; d < per_distribution.size(); ++d) {
      if (per_distribution[d] == RationalPool::kZero) continue;
      const auto [source, action] = distribution_choices_[d];
      table.choice[std::size_t{source} * num_actions + action] =
          checked_value(values_[per_distribution[d]], structure.range);
    }
    return table;
  }

  // A reward the catalog carries as a double must be one (support/double_range.hpp).
  ValueId checked_value(const Rational& value, SourceRange where) {
    const DoubleFit fit = double_fit(value);
    if (fit != DoubleFit::kFaithful && fit != DoubleFit::kSubnormal) {
      diagnostics_.error(where, carried_value_message(value, fit, "reward"));
      throw ExplorationFailed{};
    }
    return values_.intern(value);
  }

  model::StateLabels labels(std::uint32_t n) {
    std::vector<std::string> names = {"init", "deadlock"};
    for (const Label& label : program_.labels)
      names.push_back(label.name);
    model::StateLabelsBuilder builder(std::move(names));
    for (const StateIndex s : initial_)
      builder.add(s, 0);
    for (const StateIndex s : deadlocks_)
      builder.add(s, 1);
    for (StateIndex s = 0; s < n; ++s) {
      store_.unpack(s, valuation_);
      for (std::size_t l = 0; l < program_.labels.size(); ++l) {
        if (evaluate([&] { return model::evaluate_bool(program_.labels[l].holds, valuation_); }))
          builder.add(s, static_cast<std::uint32_t>(l + 2));
      }
    }
    return builder.finish(n);
  }

  [[nodiscard]] std::string state_text() const {
    return model::valuation_text(program_.variables, valuation_);
  }

  const Program& program_;
  DiagnosticEngine& diagnostics_;
  const ExploreOptions& options_;
  model::StateStore store_;
  RationalPool values_;
  std::vector<std::int64_t> valuation_;  // of the state being explored, current_
  StateIndex current_ = 0;
  std::vector<std::uint64_t> stack_;  // keys of successors under construction (outcomes())
  std::vector<Rational> sums_;        // per command of a choice (outcomes())
  std::vector<std::uint64_t> key_;
  static constexpr ValueId kStateDependent = UINT32_MAX;
  std::vector<const Command*> unlabelled_;
  std::vector<std::vector<std::vector<const Command*>>> by_action_;  // [action][module][i]
  std::vector<std::uint32_t> first_update_;  // per command serial: into probability_ids_
  std::vector<ValueId> probability_ids_;     // per update; kStateDependent when not constant
  std::vector<StateIndex> initial_;
  std::vector<StateIndex> deadlocks_;
  // The matrix, built as the states are explored. Its choices are in action order per state,
  // which may not be the order found: counts and rewards follow the order found.
  model::TransitionStream stream_{0, values_};
  static constexpr std::uint64_t kExactActionCountChoices = std::uint64_t{1} << 16;
  std::uint64_t edges_found_ = 0;
  std::uint32_t num_distributions_ = 0;
  // (source, action) per distribution, where some reward structure has action rewards.
  std::vector<std::pair<StateIndex, model::ActionIndex>> distribution_choices_;
  std::vector<std::vector<ValueId>> action_rewards_;  // per structure, per distribution
  std::vector<bool> action_items_;   // per structure: whether it has items on actions
  bool has_action_rewards_ = false;  // some structure has
  std::vector<std::string> action_names_;
  std::vector<model::ActionIndex> unlabelled_ids_;
  std::vector<std::vector<model::ActionIndex>> labelled_ids_;  // per action label
  // A state's distributions (emit_state()): the action, outcomes [first, last) of row_.
  struct FoundDistribution {
    model::ActionIndex action;
    std::size_t first;
    std::size_t last;
  };
  std::vector<FoundDistribution> state_distributions_;
  // Per batch scratch (explore_all()).
  std::vector<Choice> choices_;  // of every state of the batch, in order
  std::vector<const Command*> choice_commands_;
  std::vector<std::vector<const Command*>> participants_;
  std::vector<std::size_t> pick_;                    // per module: its command in the combination
  std::vector<std::pair<StateIndex, ValueId>> row_;  // the outcomes of every choice
  std::vector<std::size_t> choice_ends_;             // per choice: where its outcomes end
  struct Pending {
    std::size_t position;  // in row_
    SourceRange cause;     // the command, should the state limit be passed
  };
  std::vector<Pending> pending_;             // successors still to look up
  std::vector<std::uint64_t> pending_keys_;  // their packed keys, words_per_state() each
  std::vector<Worked> batch_;                // the states of the batch, in order
  std::vector<ValueId> reward_ids_;  // their action rewards: per distribution, per structure
};

}  // namespace

std::optional<model::ExplicitModel> explore(const Program& program, DiagnosticEngine& diagnostics,
                                            const ExploreOptions& options) {
  return Explorer(program, diagnostics, options).run();
}

}  // namespace oasis::prism
