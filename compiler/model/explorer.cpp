#include "model/explorer.hpp"

#include <algorithm>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "model/state_store.hpp"
#include "model/transition_stream.hpp"
#include "model/valuation_text.hpp"
#include "support/double_range.hpp"
#include "support/huge_page_growth.hpp"
#include "support/text.hpp"

namespace oasis::model {
namespace {

// Raised after a diagnostic has been reported; ends exploration.
struct ExplorationFailed {};

class Explorer {
 public:
  Explorer(const ModelIR& ir, DiagnosticEngine& diagnostics, const ExploreOptions& options)
      : ir_(ir),
        diagnostics_(diagnostics),
        options_(options),
        store_(ir.variables),
        valuation_(ir.variables.size()),
        key_(store_.words_per_state()) {}

  std::optional<ExplicitModel> run() {
    if (ir_.kind == ModelKind::Continuous) {
      diagnostics_.error(ir_.range, "model " + quoted(ir_.name) +
                                        " has continuous state; it "
                                        "needs the geometry layer, not exploration");
      return std::nullopt;
    }
    try {
      prepare_tables();
      add_initial_states();
      explore_states();
      return build_model();
    } catch (const ExplorationFailed&) {
      return std::nullopt;
    }
  }

 private:
  // Per command table: for explicit models an index from (action, state) to its command,
  // so a step is a lookup rather than a scan of every guard.
  struct Table {
    const CommandTable* commands = nullptr;
    std::vector<std::vector<const Command*>> by_state;  // [action][state]; explicit only
    std::unique_ptr<TransitionStream> stream;           // edges in choice order
    bool used = false;                                  // by some context: only these are explored
    // [action][command][outcome]: a constant probability's id, interned once rather than per
    // state; kStateDependent where it depends on the state.
    std::vector<std::vector<std::vector<ValueId>>> probability_ids;
  };
  static constexpr ValueId kStateDependent = UINT32_MAX;

  // A transition of the state being explored, kept until its successors are looked up.
  struct Edge {
    std::uint32_t table;
    ActionIndex action;
    StateIndex target;  // for a pending one: its index in pending_
    ValueId probability;
    // Whether `target` is still to look up. A whole word, not a bool: an edge is built on the
    // stack and copied into edges_ by words, and a word read of a byte just written waited
    // for the store (a third of step() in the profile).
    std::uint32_t pending;
  };
  struct Pending {
    SourceRange cause;  // the outcome, should the state limit be passed
  };

  void prepare_tables() {
    const auto num_actions = static_cast<std::uint32_t>(ir_.actions.size());
    for (const CommandTable& commands : ir_.command_tables) {
      Table table;
      table.commands = &commands;
      if (ir_.kind == ModelKind::Explicit) {
        const std::size_t n = ir_.state_names.size();
        check_explicit_size(n, num_actions);
        table.by_state.assign(num_actions, std::vector<const Command*>(n, nullptr));
        for (std::uint32_t a = 0; a < num_actions; ++a) {
          for (const Command& command : commands.by_action[a])
            table.by_state[a][command.guard.slot] = &command;
        }
      }
      table.stream = std::make_unique<TransitionStream>(num_actions, values_);
      table.probability_ids = constant_probability_ids(commands);
      tables_.push_back(std::move(table));
    }
    // When every context replaces the model's commands of some action, the model's own table
    // (0) is no context's: the states only it reaches must not join the state space.
    for (const ContextIR& context : ir_.contexts)
      tables_.at(context.command_table).used = true;
  }

  std::vector<std::vector<std::vector<ValueId>>> constant_probability_ids(
      const CommandTable& commands) {
    std::vector<std::vector<std::vector<ValueId>>> ids(commands.by_action.size());
    for (std::size_t a = 0; a < commands.by_action.size(); ++a) {
      for (const Command& command : commands.by_action[a]) {
        std::vector<ValueId>& per_outcome = ids[a].emplace_back();
        for (const Outcome& outcome : command.outcomes) {
          const Expression& p = outcome.probability;
          per_outcome.push_back(p.is_constant() ? values_.intern(p.constant) : kStateDependent);
        }
      }
    }
    return ids;
  }

  void check_explicit_size(std::size_t states, std::size_t actions) {
    if (states > options_.max_states) {
      diagnostics_.error(
          ir_.range, "model lists " + std::to_string(states) + " states, more than the limit of " +
                         std::to_string(options_.max_states) + " (raise it with --max-states)");
      throw ExplorationFailed{};
    }
    if (std::uint64_t{states} * actions >= UINT32_MAX) {
      diagnostics_.error(ir_.range, "model has more than 2^32 state-action pairs");
      throw ExplorationFailed{};
    }
  }

  void add_initial_states() {
    if (ir_.kind == ModelKind::Explicit) {
      // Every declared state, in declaration order, reachable or not.
      for (std::int64_t s = 0; s < static_cast<std::int64_t>(ir_.state_names.size()); ++s) {
        const std::int64_t state[] = {s};
        intern(state, ir_.range);
      }
    }
    for (const auto& valuation : ir_.initial)
      initial_.push_back(intern(valuation, ir_.range));
  }

  std::uint32_t intern(Valuation valuation, SourceRange cause) {
    store_.pack(valuation, key_);
    return intern_key(key_, cause);
  }

  std::uint32_t intern_key(std::span<const std::uint64_t> key, SourceRange cause) {
    const auto [index, inserted] = store_.insert(key);
    if (inserted && store_.size() > options_.max_states) {
      diagnostics_.error(cause, "exploration passed the limit of " +
                                    std::to_string(options_.max_states) +
                                    " states (raise it with --max-states)");
      throw ExplorationFailed{};
    }
    // CSR arrays index (state, action) pairs with 32 bits.
    if (inserted && std::uint64_t{store_.size()} * ir_.actions.size() >= UINT32_MAX) {
      diagnostics_.error(cause, "model has more than 2^32 state-action pairs (" +
                                    std::to_string(store_.size()) + " states x " +
                                    std::to_string(ir_.actions.size()) + " actions)");
      throw ExplorationFailed{};
    }
    return index;
  }

  // States are explored in batches: the transitions of a few states are worked out first and
  // their successors looked up after, all together. A new state's slot in the store is at
  // random in a large table, a miss to memory; prefetching the slots of a whole batch lets
  // those misses overlap. Successors are interned in the order found, so the numbering is
  // that of one state at a time; a batch grows only while its lookups cannot pass a limit,
  // so that every error is reported for the state that one at a time would report.
  static constexpr std::uint32_t kBatchStates = 8;

  void explore_states() {
    const auto num_actions = static_cast<std::uint32_t>(ir_.actions.size());
    for (std::uint32_t s = 0; s < store_.size();) {
      edges_.clear();
      pending_.clear();
      pending_keys_.clear();
      batch_ends_.clear();
      std::uint32_t end = s;
      do {
        store_.unpack(end, valuation_);
        for (std::size_t t = 0; t < tables_.size(); ++t) {
          if (!tables_[t].used) continue;
          for (std::uint32_t a = 0; a < num_actions; ++a)
            step(t, end, a);
        }
        batch_ends_.push_back(edges_.size());
        ++end;
      } while (end < store_.size() && end - s < kBatchStates && lookups_cannot_fail());
      std::size_t first = 0;
      for (std::uint32_t b = s; b < end; ++b) {
        add_edges(b, std::span(edges_).subspan(first, batch_ends_[b - s] - first));
        first = batch_ends_[b - s];
        if (options_.progress && (b & 0xFFFFU) == 0xFFFFU) options_.progress(store_.size(), b + 1);
      }
      s = end;
    }
  }

  // Whether interning every successor still to look up keeps within the limits of
  // intern_key(), even if each were a new state.
  [[nodiscard]] bool lookups_cannot_fail() const {
    const std::uint64_t most = std::uint64_t{store_.size()} + pending_.size();
    return most <= options_.max_states && most * ir_.actions.size() < UINT32_MAX;
  }

  // Each table's edges of state s go to its stream in action order, as step() found them.
  void add_edges(StateIndex s, std::span<Edge> edges) {
    const std::size_t words = store_.words_per_state();
    const auto num_actions = static_cast<ChoiceIndex>(ir_.actions.size());
    const Edge* previous = nullptr;
    for (Edge& edge : edges) {
      if (edge.pending) {
        const std::span<const std::uint64_t> key(pending_keys_.data() + edge.target * words, words);
        edge.target = intern_key(key, pending_[edge.target].cause);
      }
      TransitionStream& stream = *tables_[edge.table].stream;
      if (previous == nullptr || previous->table != edge.table || previous->action != edge.action)
        stream.begin(s * num_actions + edge.action);
      stream.add(edge.target, edge.probability);
      previous = &edge;
    }
  }

  // A successor of the state being explored: itself, or one to look up in add_edges().
  // The successor's key is in key_.
  void add_successor(std::size_t t, std::uint32_t s, std::uint32_t a, ValueId p,
                     SourceRange cause) {
    if (store_.is_key_of(s, key_)) {
      edges_.push_back({static_cast<std::uint32_t>(t), a, s, p, 0});
      return;
    }
    store_.prefetch(key_);
    edges_.push_back(
        {static_cast<std::uint32_t>(t), a, static_cast<StateIndex>(pending_.size()), p, 1});
    pending_.push_back({cause});
    pending_keys_.insert(pending_keys_.end(), key_.begin(), key_.end());
  }

  const Command* enabled_command(std::size_t t, std::uint32_t s, std::uint32_t a) {
    const Table& table = tables_[t];
    if (!table.by_state.empty()) return table.by_state[a][s];
    const Command* found = nullptr;
    for (const Command& command : table.commands->by_action[a]) {
      if (!evaluate([&] { return evaluate_bool(command.guard, valuation_); })) continue;
      if (found != nullptr) {
        diagnostics_.error(command.range, "commands for action " + quoted(ir_.actions[a]) +
                                              " overlap: both are enabled in state " +
                                              state_text() + ", which an MDP does not allow");
        diagnostics_.note(found->range, "the other enabled command");
        throw ExplorationFailed{};
      }
      found = &command;
    }
    return found;
  }

  void step(std::size_t t, std::uint32_t s, std::uint32_t a) {
    const Command* command = enabled_command(t, s, a);
    if (command == nullptr) {
      missing(t, s, a);
      return;
    }
    // The sum of the state-dependent probabilities, made only when there is one: a Rational
    // costs an allocation, and most commands have constant probabilities.
    std::optional<Rational> sum;
    const Table& table = tables_[t];
    const std::vector<ValueId>& ids = table.probability_ids[a][static_cast<std::size_t>(
        command - table.commands->by_action[a].data())];
    for (std::size_t o = 0; o < command->outcomes.size(); ++o) {
      const Outcome& outcome = command->outcomes[o];
      const ValueId p = ids[o] != kStateDependent ? ids[o] : state_probability(outcome);
      if (ids[o] == kStateDependent) {
        if (!sum) sum.emplace(0);
        *sum += values_[p];
      }
      if (p == RationalPool::kZero) continue;
      // The successor is the state's key with the updated variables changed in place.
      const std::span<const std::uint64_t> current = store_.key_of(s);
      std::copy(current.begin(), current.end(), key_.begin());
      for (const Update& update : outcome.updates)
        apply(update);
      add_successor(t, s, a, p, outcome.range);
    }
    // The checker has summed the commands whose probabilities are all constant. A single
    // state-dependent one, wherever it is (not only first), leaves the sum to each state.
    if (sum) check_sum(*command, *sum);
  }

  void missing(std::size_t t, std::uint32_t s, std::uint32_t a) {
    switch (ir_.missing) {
      case MissingPolicy::SelfLoop:
        edges_.push_back({static_cast<std::uint32_t>(t), a, s, RationalPool::kOne, 0});
        return;
      case MissingPolicy::Disabled:
        return;
      case MissingPolicy::Error:
        diagnostics_.error(ir_.range, "in state " + state_text() + " no command of action " +
                                          quoted(ir_.actions[a]) +
                                          " is enabled (add one, or write 'default self;' or "
                                          "'default disabled;' in the model)");
        throw ExplorationFailed{};
    }
  }

  // A probability that depends on the state (constant ones are interned once, in the tables).
  ValueId state_probability(const Outcome& outcome) {
    const Expression& p = outcome.probability;
    const Rational value = evaluate([&] { return evaluate_number(p, valuation_); });
    if (value < 0 || value > 1) {
      diagnostics_.error(p.range, "probability " + describe(value) + " in state " + state_text() +
                                      " is " + (value < 0 ? "negative" : "greater than 1"));
      throw ExplorationFailed{};
    }
    const ValueId id = values_.intern(value);
    check_carried(id, "probability", p.range);
    return id;
  }

  void check_sum(const Command& command, const Rational& state_dependent_sum) {
    Rational sum = state_dependent_sum;
    for (const Outcome& outcome : command.outcomes) {
      if (outcome.probability.is_constant()) sum += outcome.probability.constant;
    }
    if (sum != 1) {
      diagnostics_.error(command.range, "in state " + state_text() + " the probabilities sum to " +
                                            describe(sum) + ", not 1");
      throw ExplorationFailed{};
    }
  }

  // Every update reads the state being explored, never the successor.
  void apply(const Update& update) {
    const std::int64_t value = evaluate([&] { return evaluate_int(update.value, valuation_); });
    const DiscreteVariable& variable = ir_.variables[update.variable];
    if (value < variable.low || value > variable.high) {
      diagnostics_.error(update.range,
                         range_violation(variable, value) + ", in state " + state_text());
      throw ExplorationFailed{};
    }
    store_.set(key_, update.variable, value);
  }

  // Runs an evaluation, turning an evaluation error into a diagnostic about this state.
  template <typename Evaluate>
  auto evaluate(Evaluate&& run) -> decltype(run()) {
    try {
      return run();
    } catch (const EvaluationError& error) {
      diagnostics_.error(error.where, std::string(error.what()) + " in state " + state_text());
      throw ExplorationFailed{};
    }
  }

  // A state-dependent value the catalog must carry as a double (support/double_range.hpp).
  // Each distinct value is judged once: a warning for a lossy value is not repeated for every
  // state that has it, and an error ends the exploration.
  void check_carried(ValueId id, std::string_view what, SourceRange where) {
    if (id < judged_.size() && judged_[id]) return;
    if (judged_.size() <= id) judged_.resize(std::size_t{id} + 1, false);
    judged_[id] = true;
    const DoubleFit fit = double_fit(values_[id]);
    if (fit == DoubleFit::kFaithful) return;
    const std::string message = carried_value_message(values_[id], fit, what);
    if (fit == DoubleFit::kSubnormal) {
      diagnostics_.warning(where, message + " (first in state " + state_text() + ")");
      return;
    }
    diagnostics_.error(where, message + " in state " + state_text());
    throw ExplorationFailed{};
  }

  [[nodiscard]] std::string state_text() const {
    if (ir_.kind == ModelKind::Explicit) return quoted(ir_.state_names[valuation_[0]]);
    return valuation_text(ir_.variables, valuation_);
  }

  ExplicitModel build_model() {
    store_.end_lookups();
    ExplicitModel model;
    model.name = ir_.name;
    model.actions = ir_.actions;
    model.switching = ir_.switching;
    model.objective = ir_.objective;
    model.observation = ir_.observation;
    model.properties = ir_.properties;
    fill_state_space(model.states);
    std::vector<std::shared_ptr<const TransitionMatrix>> matrices;
    for (Table& table : tables_) {
      if (!table.used) {
        matrices.push_back(nullptr);
        continue;
      }
      matrices.push_back(
          std::make_shared<const TransitionMatrix>(table.stream->finish(store_.size(), values_)));
      table.stream.reset();
    }
    for (const ContextIR& context : ir_.contexts) {
      model.contexts.push_back({context.name, matrices[context.command_table], rewards(context)});
    }
    model.values = std::move(values_);
    return model;
  }

  void fill_state_space(StateSpace& space) {
    space.size = store_.size();
    space.initial = initial_;
    if (ir_.kind == ModelKind::Explicit) {
      space.names = ir_.state_names;
      return;
    }
    for (const DiscreteVariable& var : ir_.variables)
      space.variables.push_back(var.name);
    reserve_huge(space.valuations, std::size_t{store_.size()} * ir_.variables.size());
    space.valuations.resize(std::size_t{store_.size()} * ir_.variables.size());
    for (std::uint32_t s = 0; s < store_.size(); ++s) {
      store_.unpack(s, std::span(space.valuations)
                           .subspan(std::size_t{s} * ir_.variables.size(), ir_.variables.size()));
    }
  }

  RewardTable rewards(const ContextIR& context) {
    const std::uint32_t n = store_.size();
    const std::size_t num_actions = ir_.actions.size();
    RewardTable table;
    table.state.assign(n, RationalPool::kZero);
    bool has_action_rewards = false;
    for (const Reward& reward : context.rewards)
      has_action_rewards |= reward.action.has_value();
    if (has_action_rewards) table.choice.assign(std::size_t{n} * num_actions, RationalPool::kZero);
    for (std::uint32_t s = 0; s < n; ++s) {
      store_.unpack(s, valuation_);
      for (const Reward& reward : context.rewards) {
        if (!evaluate([&] { return evaluate_bool(reward.guard, valuation_); })) continue;
        ValueId& slot =
            reward.action ? table.choice[s * num_actions + *reward.action] : table.state[s];
        const Rational value = evaluate([&] { return evaluate_number(reward.value, valuation_); });
        const bool summed = slot != RationalPool::kZero;
        slot = summed ? values_.intern(values_[slot] + value) : values_.intern(value);
        // A constant alone was judged by the checker already.
        if (summed || !reward.value.is_constant())
          check_carried(slot, "reward", reward.value.range);
      }
    }
    return table;
  }

  const ModelIR& ir_;
  DiagnosticEngine& diagnostics_;
  std::vector<bool> judged_;  // by ValueId: checked by check_carried() already
  const ExploreOptions& options_;
  StateStore store_;
  std::vector<std::int64_t> valuation_;
  std::vector<std::uint64_t> key_;  // of the successor being built, or a state to intern
  std::vector<Table> tables_;
  std::vector<Edge> edges_;                  // of the states being explored (a batch)
  std::vector<std::size_t> batch_ends_;      // where each one's edges end in edges_
  std::vector<Pending> pending_;             // its successors still to look up
  std::vector<std::uint64_t> pending_keys_;  // their packed keys, words_per_state() each
  std::vector<std::uint32_t> initial_;
  RationalPool values_;
};

}  // namespace

std::optional<ExplicitModel> explore(const ModelIR& ir, DiagnosticEngine& diagnostics,
                                     const ExploreOptions& options) {
  if (ir.imported) {
    // The program is the PRISM front end's to read (prism/imported_catalog.hpp), a layer up.
    diagnostics.error(ir.imported->path_range,
                      "this spec imports its model: it is explored by the PRISM front end");
    return std::nullopt;
  }
  return Explorer(ir, diagnostics, options).run();
}

}  // namespace oasis::model
