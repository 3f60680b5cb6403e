#include "verify/scheduler_check.hpp"

#include <algorithm>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <optional>
#include <unordered_map>

#include "support/text.hpp"
#include "verify/reachability_property.hpp"

namespace oasis::verify {
namespace {

using model::ActionIndex;
using model::ChoiceIndex;
using model::StateIndex;

constexpr ActionIndex kNoAction = UINT32_MAX;  // a deadlock, or a state whose choice is moot
constexpr std::uint32_t kUnsolved = UINT32_MAX;

// The scheduler is wrong: "FAILED: ...".
struct Failure {
  std::string message;
};
// verify does not check it: "not checked: ...".
struct Refusal {
  std::string message;
};

// A value as verdicts print it: the exact fraction, or a summary when it is long.
std::string fraction(const Rational& value) {
  const std::string text = to_string(value);
  return text.size() <= 64 ? text : describe(value);
}

// What every scheduler of a model shares: the choices leading into each state (CSR), and the
// states and actions by name.
struct ModelIndex {
  explicit ModelIndex(const model::ExplicitModel& model)
      : matrix(*model.contexts.front().transitions) {
    const std::uint32_t n = matrix.num_states;
    incoming_begin.assign(n + 1, 0);
    for (StateIndex t : matrix.edge_target)
      ++incoming_begin[t + 1];
    for (StateIndex s = 0; s < n; ++s)
      incoming_begin[s + 1] += incoming_begin[s];
    incoming.resize(matrix.edge_target.size());
    std::vector<std::uint32_t> fill(incoming_begin.begin(), incoming_begin.end() - 1);
    for (StateIndex s = 0; s < n; ++s)
      for (ActionIndex a = 0; a < matrix.num_actions; ++a)
        for (model::EdgeIndex e = matrix.edges_begin(s, a); e < matrix.edges_end(s, a); ++e)
          incoming[fill[matrix.edge_target[e]]++] = matrix.choice(s, a);
    for (StateIndex s = 0; s < n; ++s)
      state_by_name.emplace(model.states.name(s), s);
    for (ActionIndex a = 0; a < model.num_actions(); ++a)
      action_by_name.emplace(model.actions[a], a);
  }

  const model::TransitionMatrix& matrix;
  std::vector<std::uint32_t> incoming_begin;  // num_states + 1
  std::vector<ChoiceIndex> incoming;          // the choices with an edge into the state
  std::unordered_map<std::string, StateIndex> state_by_name;
  std::unordered_map<std::string, ActionIndex> action_by_name;
};

class SchedulerChecker {
 public:
  SchedulerChecker(const model::ExplicitModel& model, const ModelIndex& index,
                   const SchedulerCheckOptions& options)
      : model_(model), index_(index), matrix_(index.matrix), options_(options) {}

  // The verdict's text after "scheduler for '...': ".
  std::string check(const SchedulerEntry& entry) {
    if (entry.step_bounded)
      throw Refusal{
          "a step-bounded scheduler (\"by_step\"); verify checks the memoryless schedulers of "
          "unbounded Pmax/Pmin reachability, and 'oasisc query' answers the rest"};
    std::string error;
    auto property = read_reachability_property(entry.property, model_, error);
    if (!property) throw Refusal{error};
    property_ = std::move(*property);
    read_choices(entry);
    precompute();
    resolve_nulls();
    solve();
    if (property_.maximise) {
      check_max();
    } else {
      check_min();
    }
    return "optimal; " + initial_values();
  }

 private:
  std::string name(StateIndex s) const { return model_.states.name(s); }
  std::string action_name(ActionIndex a) const { return quoted(model_.actions[a]); }
  bool live(StateIndex s) const { return property_.until[s] && !property_.target[s]; }
  std::uint32_t num_states() const { return matrix_.num_states; }

  // 1. Every state once, every action named enabled in its state.
  void read_choices(const SchedulerEntry& entry) {
    chosen_.assign(num_states(), kNoAction);
    null_.assign(num_states(), false);
    std::vector<bool> seen(num_states(), false);
    for (const StateChoice& choice : entry.memoryless) {
      const auto state = index_.state_by_name.find(choice.state);
      if (state == index_.state_by_name.end())
        throw Failure{"the model has no state " + quoted(choice.state)};
      const StateIndex s = state->second;
      if (seen[s]) throw Failure{"state " + name(s) + " is listed twice"};
      seen[s] = true;
      if (!choice.action) {
        null_[s] = true;
        continue;
      }
      const auto action = index_.action_by_name.find(*choice.action);
      if (action == index_.action_by_name.end())
        throw Failure{"in state " + name(s) + ", the model has no action " +
                      quoted(*choice.action)};
      if (!matrix_.enabled(s, action->second))
        throw Failure{"in state " + name(s) + ", action " + action_name(action->second) +
                      " is not enabled"};
      chosen_[s] = action->second;
    }
    for (StateIndex s = 0; s < num_states(); ++s) {
      if (seen[s]) continue;
      std::size_t missing = 0;
      for (StateIndex t = s; t < num_states(); ++t)
        missing += seen[t] ? 0 : 1;
      throw Failure{"state " + name(s) + " is not in the file" +
                    (missing > 1 ? " (nor " + std::to_string(missing - 1) + " more)" : "")};
    }
  }

  // The states found from `seeds` backwards along the choices (s, a) that `follow` accepts.
  std::vector<bool> backwards(const std::vector<bool>& seeds,
                              const std::function<bool(StateIndex, ActionIndex)>& follow) const {
    std::vector<bool> found = seeds;
    std::deque<StateIndex> queue;
    for (StateIndex s = 0; s < num_states(); ++s)
      if (seeds[s]) queue.push_back(s);
    while (!queue.empty()) {
      const StateIndex t = queue.front();
      queue.pop_front();
      for (std::uint32_t i = index_.incoming_begin[t]; i < index_.incoming_begin[t + 1]; ++i) {
        const StateIndex s = index_.incoming[i] / matrix_.num_actions;
        if (found[s] || !follow(s, index_.incoming[i] % matrix_.num_actions)) continue;
        found[s] = true;
        queue.push_back(s);
      }
    }
    return found;
  }

  std::size_t num_enabled(StateIndex s) const {
    std::size_t count = 0;
    for (ActionIndex a = 0; a < matrix_.num_actions; ++a)
      count += matrix_.enabled(s, a) ? 1 : 0;
    return count;
  }

  // The graph sets of the header: can_reach_ (some path reaches T: Pmax > 0), in_a_ (every
  // scheduler reaches T with positive probability: Pmin > 0; Z is its complement) and
  // below_one_ (some path avoiding T reaches Z: Pmin < 1).
  void precompute() {
    const auto any_live = [&](StateIndex s, ActionIndex) { return live(s); };
    can_reach_ = backwards(property_.target, any_live);

    // A: T, then every live state with an action all of whose actions have a successor in A.
    in_a_ = property_.target;
    std::vector<std::size_t> remaining(num_states(), 0);
    for (StateIndex s = 0; s < num_states(); ++s)
      if (live(s)) remaining[s] = num_enabled(s);
    std::vector<bool> counted(std::size_t{num_states()} * matrix_.num_actions, false);
    std::deque<StateIndex> queue;
    for (StateIndex s = 0; s < num_states(); ++s)
      if (in_a_[s]) queue.push_back(s);
    while (!queue.empty()) {
      const StateIndex t = queue.front();
      queue.pop_front();
      for (std::uint32_t i = index_.incoming_begin[t]; i < index_.incoming_begin[t + 1]; ++i) {
        const ChoiceIndex c = index_.incoming[i];
        const StateIndex s = c / matrix_.num_actions;
        if (!live(s) || in_a_[s] || counted[c]) continue;
        counted[c] = true;  // this action of s has a successor in A
        if (--remaining[s] > 0) continue;
        in_a_[s] = true;
        queue.push_back(s);
      }
    }
    std::vector<bool> zero(num_states());
    for (StateIndex s = 0; s < num_states(); ++s)
      zero[s] = !in_a_[s];
    below_one_ = backwards(zero, any_live);
  }

  // Each live state's action in the induced chain, and the states whose value is fixed
  // whatever is chosen (the nulls of 0 and 1).
  void resolve_nulls() {
    fixed_.assign(num_states(), std::nullopt);
    for (StateIndex s = 0; s < num_states(); ++s) {
      if (!live(s)) {
        fixed_[s] = property_.target[s] ? 1 : 0;
        continue;
      }
      if (!null_[s]) continue;
      const std::size_t actions = num_enabled(s);
      if (actions == 0 || (actions > 1 && !can_reach_[s])) {
        fixed_[s] = 0;  // a deadlock, or no path to the target whatever is chosen
      } else if (actions == 1) {
        for (ActionIndex a = 0; a < matrix_.num_actions; ++a)
          if (matrix_.enabled(s, a)) chosen_[s] = a;
      } else if (!below_one_[s]) {
        fixed_[s] = 1;
      } else {
        throw Failure{"in state " + name(s) +
                      ", the file leaves the action open (null), but "
                      "the choice matters there: some path reaches the target from it and some "
                      "scheduler misses the target from it"};
      }
    }
  }

  const Rational& value(StateIndex s) const {
    if (solved_index_[s] != kUnsolved) return solved_[solved_index_[s]];
    return fixed_[s] == 1 ? one_ : zero_;
  }

  void check_bits(const Rational& q) const {
    if (bit_size(q) > options_.max_number_bits)
      throw Refusal{"the exact solve meets a number that " +
                    too_long_message(q, options_.max_number_bits)};
  }

  // 2. The induced chain's values: 1 where fixed to 1 (T and nulls of 1), 0 where fixed to 0
  // or where no chosen edge leads towards a 1, the rest by elimination.
  void solve() {
    std::vector<bool> ones(num_states());
    for (StateIndex s = 0; s < num_states(); ++s)
      ones[s] = fixed_[s] == 1;
    const std::vector<bool> reaching =
        backwards(ones, [&](StateIndex s, ActionIndex a) { return !fixed_[s] && chosen_[s] == a; });
    std::vector<StateIndex> unknowns;
    solved_index_.assign(num_states(), kUnsolved);
    for (StateIndex s = 0; s < num_states(); ++s) {
      if (fixed_[s]) continue;
      if (!reaching[s]) {
        fixed_[s] = 0;
        continue;
      }
      solved_index_[s] = static_cast<std::uint32_t>(unknowns.size());
      unknowns.push_back(s);
    }
    const std::size_t m = unknowns.size();
    if (m > kMaxSolvedStates)
      throw Refusal{"the induced chain has " + std::to_string(m) +
                    " states to solve exactly, more than verify's limit of " +
                    std::to_string(kMaxSolvedStates)};

    // x_k = b_k + sum_j rows[k][j] x_j over the unknowns.
    std::vector<std::map<std::uint32_t, Rational>> rows(m);
    std::vector<Rational> b(m);
    std::vector<std::vector<std::uint32_t>> refers(m);  // the rows with an entry in column j
    for (std::uint32_t k = 0; k < m; ++k) {
      const StateIndex s = unknowns[k];
      const ActionIndex a = chosen_[s];
      for (model::EdgeIndex e = matrix_.edges_begin(s, a); e < matrix_.edges_end(s, a); ++e) {
        const StateIndex t = matrix_.edge_target[e];
        const Rational& p = model_.values[matrix_.edge_probability[e]];
        if (solved_index_[t] != kUnsolved) {
          rows[k][solved_index_[t]] += p;
          if (solved_index_[t] != k) refers[solved_index_[t]].push_back(k);
        } else if (fixed_[t] == 1) {
          b[k] += p;
        }
      }
    }
    std::size_t work = 0;
    for (std::uint32_t k = 0; k < m; ++k) {
      auto& row = rows[k];
      if (const auto self = row.find(k); self != row.end()) {
        const Rational remaining = 1 - self->second;
        row.erase(self);
        // Cannot happen: every unknown reaches T with positive probability.
        if (remaining <= 0)
          throw Failure{"the induced chain's equations are singular at state " + name(unknowns[k])};
        for (auto& [j, coefficient] : row) {
          coefficient /= remaining;
          check_bits(coefficient);
        }
        b[k] /= remaining;
        check_bits(b[k]);
      }
      for (const std::uint32_t r : refers[k]) {
        if (r <= k) continue;  // an eliminated row: back substitution uses its entry
        const auto entry = rows[r].find(k);
        if (entry == rows[r].end()) continue;
        const Rational factor = entry->second;
        rows[r].erase(entry);
        for (const auto& [j, coefficient] : row) {
          const auto [at, added] = rows[r].try_emplace(j);
          at->second += factor * coefficient;
          if (added && j != r) refers[j].push_back(r);
        }
        b[r] += factor * b[k];
        work += row.size() + 1;
        if (work > kMaxEliminationWork)
          throw Refusal{"the exact solve of the induced chain (" + std::to_string(m) +
                        " states) needs more than verify's limit of " +
                        std::to_string(kMaxEliminationWork) + " multiply-adds"};
      }
      std::vector<std::uint32_t>().swap(refers[k]);
    }
    solved_.assign(m, Rational(0));
    for (std::uint32_t k = m; k-- > 0;) {
      Rational x = b[k];
      for (const auto& [j, coefficient] : rows[k])
        x += coefficient * solved_[j];
      check_bits(x);
      solved_[k] = std::move(x);
    }
  }

  Rational expected(StateIndex s, ActionIndex a) const {
    Rational sum = 0;
    for (model::EdgeIndex e = matrix_.edges_begin(s, a); e < matrix_.edges_end(s, a); ++e) {
      const Rational& v = value(matrix_.edge_target[e]);
      if (v != 0) sum += model_.values[matrix_.edge_probability[e]] * v;
    }
    return sum;
  }

  // A state where the certificate fails: `action` gives `gives`, the scheduler `value`.
  struct Violation {
    StateIndex state;
    ActionIndex action;
    Rational gives;
    Rational value;
  };

  // The widest gap first (where a swapped-in action is, typically), then up to two more, and
  // how many states fail in all.
  [[noreturn]] void fail_certificate(std::vector<Violation>& violations) const {
    std::stable_sort(violations.begin(), violations.end(), [](const auto& x, const auto& y) {
      return abs(x.gives - x.value) > abs(y.gives - y.value);
    });
    std::string message;
    for (std::size_t i = 0; i < violations.size() && i < 3; ++i) {
      const Violation& v = violations[i];
      message += (i == 0 ? "in state " : "; in state ") + name(v.state) + ", action " +
                 action_name(v.action) + " gives " + fraction(v.gives) +
                 (v.gives > v.value ? " > " : " < ") + fraction(v.value) +
                 (i == 0 ? ", the scheduler's value there" : "");
    }
    if (violations.size() > 3)
      message += " (" + std::to_string(violations.size()) + " states fail in all)";
    throw Failure{message};
  }

  // The action of s that gives the most (Pmax) or the least (Pmin) when that beats v(s).
  std::optional<Violation> violation_at(StateIndex s) const {
    std::optional<Violation> worst;
    for (ActionIndex a = 0; a < matrix_.num_actions; ++a) {
      if (!matrix_.enabled(s, a)) continue;
      Rational gives = expected(s, a);
      const Rational& reference = worst ? worst->gives : value(s);
      if (property_.maximise ? gives > reference : gives < reference)
        worst = Violation{s, a, std::move(gives), value(s)};
    }
    return worst;
  }

  // 3. Pmax: v(s) >= sum_t P(s,a,t) v(t) at every live s and every enabled a.
  void check_max() const {
    std::vector<Violation> violations;
    for (StateIndex s = 0; s < num_states(); ++s) {
      if (!live(s)) continue;
      if (auto violation = violation_at(s)) violations.push_back(std::move(*violation));
    }
    if (!violations.empty()) fail_certificate(violations);
  }

  // 3. Pmin: v = 0 on Z, and v(s) <= sum_t P(s,a,t) v(t) at every other live s and enabled a.
  void check_min() const {
    std::vector<Violation> violations;
    for (StateIndex s = 0; s < num_states(); ++s) {
      if (!live(s)) continue;
      if (!in_a_[s]) {
        if (value(s) == 0) continue;
        // Some action keeps every successor in Z (s is live and its value is not 0, so it
        // has one: a deadlock's value is 0).
        ActionIndex avoiding = kNoAction;
        for (ActionIndex a = 0; a < matrix_.num_actions && avoiding == kNoAction; ++a) {
          if (!matrix_.enabled(s, a)) continue;
          bool inside = true;
          for (model::EdgeIndex e = matrix_.edges_begin(s, a); e < matrix_.edges_end(s, a); ++e)
            inside = inside && !in_a_[matrix_.edge_target[e]];
          if (inside) avoiding = a;
        }
        throw Failure{"in state " + name(s) + ", the scheduler's value is " + fraction(value(s)) +
                      ", but the minimum is 0: action " +
                      (avoiding == kNoAction ? std::string("(none)") : action_name(avoiding)) +
                      " never leaves states from which the target can be avoided forever"};
      }
      if (auto violation = violation_at(s)) violations.push_back(std::move(*violation));
    }
    if (!violations.empty()) fail_certificate(violations);
  }

  std::string initial_values() const {
    const std::vector<StateIndex>& initial = model_.states.initial;
    if (initial.empty()) return "the model has no initial state";
    if (initial.size() == 1)
      return "value " + fraction(value(initial.front())) + " in the initial state";
    const Rational* low = &value(initial.front());
    const Rational* high = low;
    for (StateIndex s : initial) {
      if (value(s) < *low) low = &value(s);
      if (value(s) > *high) high = &value(s);
    }
    const std::string count = std::to_string(initial.size());
    if (*low == *high) return "value " + fraction(*low) + " in all " + count + " initial states";
    return "values from " + fraction(*low) + " to " + fraction(*high) + " in the " + count +
           " initial states";
  }

  const model::ExplicitModel& model_;
  const ModelIndex& index_;
  const model::TransitionMatrix& matrix_;
  const SchedulerCheckOptions& options_;
  ReachabilityProperty property_;
  std::vector<ActionIndex> chosen_;  // per state: the file's action, kNoAction for null
  std::vector<bool> null_;
  std::vector<bool> can_reach_, in_a_, below_one_;
  std::vector<std::optional<int>> fixed_;  // 0 or 1 where the value is known without solving
  std::vector<std::uint32_t> solved_index_;
  std::vector<Rational> solved_;
  const Rational zero_{0};
  const Rational one_{1};
};

std::string item_name(const SchedulerEntry& entry) {
  std::string item = "scheduler";
  if (entry.name) item += " \"" + text::printable_excerpt(*entry.name) + "\"";
  return item + " for '" + text::printable_excerpt(entry.property, 200) + "'";
}

}  // namespace

std::vector<CatalogCheck> check_schedulers(const model::ExplicitModel& model,
                                           const SchedulerFile& file,
                                           const SchedulerCheckOptions& options) {
  for (const model::Context& context : model.contexts) {
    if (context.transitions != model.contexts.front().transitions)
      return {{"schedulers",
               "FAILED: context " + quoted(context.name) +
                   " has transitions of its own; a scheduler file is for models whose contexts "
                   "share theirs",
               false}};
  }
  if (model.contexts.empty()) return {{"schedulers", "FAILED: the model has no context", false}};
  const ModelIndex index(model);
  std::vector<CatalogCheck> checks;
  for (const SchedulerEntry& entry : file.schedulers) {
    CatalogCheck check{item_name(entry), "", false};
    try {
      check.verdict = SchedulerChecker(model, index, options).check(entry);
      check.ok = true;
    } catch (const Failure& failure) {
      check.verdict = "FAILED: " + failure.message;
    } catch (const Refusal& refusal) {
      check.verdict = "not checked: " + refusal.message;
    }
    checks.push_back(std::move(check));
  }
  return checks;
}

}  // namespace oasis::verify
