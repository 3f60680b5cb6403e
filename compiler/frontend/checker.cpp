#include "frontend/checker.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <utility>

#include "model/affine.hpp"
#include "frontend/catalog_checker.hpp"
#include "frontend/expression_checker.hpp"
#include "frontend/observation_checker.hpp"
#include "frontend/scope.hpp"
#include "support/double_range.hpp"
#include "support/text.hpp"

namespace oasis::frontend {
namespace {

using model::Command;
using model::Expression;
using model::ModelKind;
using model::Op;
using model::Type;

// support/limits.hpp says why each is what it is.
constexpr std::size_t kMaxContexts = limits::kMaxContexts;
constexpr std::int64_t kMaxVariableRange = limits::kMaxVariableRange;

class Checker {
 public:
  Checker(const ast::SpecFile& spec, DiagnosticEngine& diagnostics, std::size_t max_number_bits)
      : spec_(spec),
        diagnostics_(diagnostics),
        expressions_(scope_, diagnostics, max_number_bits) {}

  std::optional<model::ModelIR> run() {
    const ast::MdpDecl* mdp = single_model();
    if (mdp == nullptr) return std::nullopt;
    ir_.name = std::string(mdp->name.text);
    ir_.range = mdp->range;
    ir_.objective_range = mdp->name.range;
    if (!decide_kind(*mdp)) return std::nullopt;
    declare_actions(*mdp);
    declare_constants(*mdp);
    declare_states_or_variables(*mdp);
    declare_regions(*mdp);
    check_settings(*mdp);
    if (diagnostics_.has_errors()) return std::nullopt;  // names must be sound before bodies

    base_ = lower_behaviour(mdp->behaviour, /*is_context=*/false);
    if (ir_.kind == ModelKind::Explicit) check_explicit_complete();
    if (ir_.kind == ModelKind::Continuous) check_dynamics_complete(*mdp);
    check_catalog(*mdp);
    if (diagnostics_.has_errors()) return std::nullopt;
    return std::move(ir_);
  }

 private:
  // Everything a model or context body says, lowered. `transitions` is per (state, action)
  // for explicit models and per action for factored ones.
  struct LoweredBehaviour {
    std::vector<std::vector<Command>> commands_by_action;
    std::vector<bool> overrides_action;  // factored: this body gives commands for the action
    std::map<std::pair<std::uint32_t, std::uint32_t>, Command> explicit_transitions;
    std::vector<model::Reward> rewards;
    bool has_rewards = false;
    std::vector<std::optional<model::AffineDynamics>> dynamics;
    bool empty = true;
  };

  // A checked `disturbance` item: the continuous variable it acts on, and how.
  struct LoweredDisturbance {
    std::uint32_t variable = 0;
    model::DisturbanceModel model;
  };

  // ---- model-level declarations -----------------------------------------------------------

  const ast::MdpDecl* single_model() {
    if (spec_.mdps.empty()) {
      const FileId file = spec_.file;
      diagnostics_.error(SourceLocation{file, 0},
                         "spec declares no model: expected an 'mdp NAME { ... }' block");
      return nullptr;
    }
    for (std::size_t i = 1; i < spec_.mdps.size(); ++i) {
      diagnostics_.error(spec_.mdps[i].name.range,
                         "a spec holds one 'mdp'; contexts of the same "
                         "model go in its 'catalog'");
    }
    for (std::size_t i = 1; i < spec_.catalogs.size(); ++i) {
      diagnostics_.error(spec_.catalogs[i].range, "a spec holds at most one 'catalog'");
    }
    return &spec_.mdps.front();
  }

  bool decide_kind(const ast::MdpDecl& mdp) {
    const bool has_states = !mdp.states.empty();
    const ast::VarDecl* discrete = nullptr;
    const ast::VarDecl* continuous = nullptr;
    for (const auto& var : mdp.variables)
      (var.continuous ? continuous : discrete) = &var;
    if (has_states && (discrete || continuous)) {
      const auto& var = discrete ? *discrete : *continuous;
      diagnostics_.error(var.range, "a model lists its states or declares variables, not both");
      return false;
    }
    if (discrete && continuous) {
      diagnostics_.error(continuous->range,
                         "mixing discrete ('var') and continuous variables is not supported");
      return false;
    }
    if (!has_states && !discrete && !continuous) {
      diagnostics_.error(mdp.name.range, "model " + quoted(mdp.name.text) +
                                             " has no states: list them with 'states' or "
                                             "declare variables with 'var' or 'continuous'");
      return false;
    }
    ir_.kind =
        has_states ? ModelKind::Explicit : (discrete ? ModelKind::Factored : ModelKind::Continuous);
    return true;
  }

  void declare_actions(const ast::MdpDecl& mdp) {
    if (mdp.actions.empty()) {
      diagnostics_.error(mdp.name.range, "model " + quoted(mdp.name.text) +
                                             " declares no actions (add 'actions a, b;')");
    }
    for (const ast::Name& action : mdp.actions) {
      const auto index = static_cast<model::ActionIndex>(ir_.actions.size());
      if (actions_.declare(action.text, action.range, index, "action", diagnostics_)) {
        ir_.actions.emplace_back(action.text);
      }
    }
  }

  void declare_constants(const ast::MdpDecl& mdp) {
    for (const ast::ConstDecl& constant : mdp.constants) {
      auto value = expressions_.check(*constant.value, ExpressionRules{.place = "in a constant"});
      if (value && !value->is_constant()) {
        diagnostics_.error(constant.value->range, "constant " + quoted(constant.name.text) +
                                                      " needs a value known before exploration");
        value.reset();
      }
      Symbol symbol{SymbolKind::Constant,
                    0,
                    value ? value->type : Type::Int,
                    value ? value->constant : Rational(0),
                    constant.name.range,
                    !value};
      scope_.declare(constant.name.text, constant.name.range, std::move(symbol), "name",
                     diagnostics_);
    }
  }

  void declare_states_or_variables(const ast::MdpDecl& mdp) {
    switch (ir_.kind) {
      case ModelKind::Explicit:
        declare_states(mdp);
        break;
      case ModelKind::Factored:
        declare_discrete_variables(mdp);
        break;
      case ModelKind::Continuous:
        declare_continuous_variables(mdp);
        break;
    }
    if (ir_.kind != ModelKind::Explicit && !mdp.initial.empty()) {
      diagnostics_.error(mdp.initial.front().range,
                         "'init' lists initial states of explicit models; give variables an "
                         "'init' value instead");
    }
  }

  void declare_states(const ast::MdpDecl& mdp) {
    for (const ast::Name& state : mdp.states) {
      const auto index = static_cast<std::uint32_t>(ir_.state_names.size());
      Symbol symbol{SymbolKind::State, index, Type::Bool, 0, state.range};
      if (scope_.declare(state.text, state.range, std::move(symbol), "name", diagnostics_)) {
        ir_.state_names.emplace_back(state.text);
        state_ranges_.push_back(state.range);
      }
    }
    const auto count = static_cast<std::int64_t>(ir_.state_names.size());
    ir_.variables.push_back({"state", 0, count - 1, 0, mdp.name.range});
    for (const ast::Name& initial : mdp.initial) {
      if (auto state = resolve_state(initial)) ir_.initial.push_back({*state});
    }
    if (ir_.initial.empty() && count > 0) ir_.initial.push_back({0});
  }

  std::optional<std::uint32_t> resolve_state(const ast::Name& name) {
    const auto* entry = scope_.find(name.text);
    if (entry == nullptr || entry->value.kind != SymbolKind::State) {
      diagnostics_.error(name.range, (entry ? std::string(describe(entry->value.kind)) + " "
                                            : std::string("unknown state ")) +
                                         quoted(name.text) + (entry ? " is not a state" : ""));
      return std::nullopt;
    }
    return entry->value.index;
  }

  std::optional<model::ActionIndex> resolve_action(const ast::Name& name) {
    const auto* entry = actions_.find(name.text);
    if (entry == nullptr) {
      diagnostics_.error(name.range, "unknown action " + quoted(name.text));
      return std::nullopt;
    }
    return entry->value;
  }

  void declare_discrete_variables(const ast::MdpDecl& mdp) {
    std::vector<std::int64_t> initial;
    for (const ast::VarDecl& var : mdp.variables) {
      auto low = expressions_.constant_integer(*var.low, "a lower bound");
      auto high = expressions_.constant_integer(*var.high, "an upper bound");
      if (!low || !high) continue;
      if (*low > *high) {
        diagnostics_.error(var.range, "empty range: lower bound " + std::to_string(*low) +
                                          " is above upper bound " + std::to_string(*high));
        continue;
      }
      if (static_cast<__int128>(*high) - *low >= kMaxVariableRange) {
        diagnostics_.error(
            var.range, "range of " + quoted(var.name.text) + " is too large (at most 2^40 values)");
        continue;
      }
      std::int64_t init = *low;
      if (var.init) {
        auto value = expressions_.constant_integer(*var.init, "an initial value");
        if (!value) continue;
        if (*value < *low || *value > *high) {
          diagnostics_.error(var.init->range, "initial value " + std::to_string(*value) +
                                                  " is outside the range [" + std::to_string(*low) +
                                                  " .. " + std::to_string(*high) + "]");
          continue;
        }
        init = *value;
      }
      const auto index = static_cast<std::uint32_t>(ir_.variables.size());
      Symbol symbol{SymbolKind::Variable, index, Type::Int, 0, var.name.range};
      if (scope_.declare(var.name.text, var.name.range, std::move(symbol), "name", diagnostics_)) {
        ir_.variables.push_back({std::string(var.name.text), *low, *high, init, var.range});
        initial.push_back(init);
      }
    }
    ir_.initial.push_back(std::move(initial));
  }

  void declare_continuous_variables(const ast::MdpDecl& mdp) {
    for (const ast::VarDecl& var : mdp.variables) {
      auto low = expressions_.constant_number(*var.low, "a lower bound");
      auto high = expressions_.constant_number(*var.high, "an upper bound");
      if (!low || !high) continue;
      if (*low >= *high) {
        diagnostics_.error(var.range, "empty range: lower bound " + describe(*low) +
                                          " is not below upper bound " + describe(*high));
        continue;
      }
      const auto index = static_cast<std::uint32_t>(ir_.continuous.size());
      Symbol symbol{SymbolKind::ContinuousVariable, index, Type::Real, 0, var.name.range};
      if (scope_.declare(var.name.text, var.name.range, std::move(symbol), "name", diagnostics_)) {
        ir_.continuous.push_back({std::string(var.name.text), *low, *high, var.range});
      }
    }
  }

  void declare_regions(const ast::MdpDecl& mdp) {
    for (const ast::RegionDecl& region : mdp.regions) {
      if (ir_.kind != ModelKind::Continuous) {
        diagnostics_.error(region.name.range,
                           "regions describe continuous state; this model has "
                           "no continuous variables");
        continue;
      }
      const ExpressionRules rules{.continuous = true, .regions = true, .place = "in a region"};
      auto condition = expressions_.check_typed(*region.constraint, rules, Type::Bool, "a region");
      if (!condition) continue;
      auto constraints = model::polyhedral_constraints(*condition, ir_.continuous.size(), ir_.regions);
      if (!constraints) {
        diagnostics_.error(region.constraint->range,
                           "a region must be a conjunction ('&') of linear inequalities over "
                           "the continuous variables");
        continue;
      }
      const auto index = static_cast<std::uint32_t>(ir_.regions.size());
      Symbol symbol{SymbolKind::Region, index, Type::Bool, 0, region.name.range};
      if (scope_.declare(region.name.text, region.name.range, std::move(symbol), "name",
                         diagnostics_)) {
        ir_.regions.push_back(
            {std::string(region.name.text), std::move(*constraints), region.range});
      }
    }
  }

  void check_settings(const ast::MdpDecl& mdp) {
    if (mdp.missing == ast::MissingTransitions::SelfLoop)
      ir_.missing = model::MissingPolicy::SelfLoop;
    if (mdp.missing == ast::MissingTransitions::Disabled)
      ir_.missing = model::MissingPolicy::Disabled;
    if (mdp.discount && mdp.horizon) {
      diagnostics_.error(mdp.horizon->range, "give a 'discount' or a 'horizon', not both");
    }
    if (mdp.discount) {
      ir_.objective_range = mdp.discount->value->range;
      check_discount(*mdp.discount->value, mdp.horizon.has_value());
    }
    if (mdp.horizon) {
      ir_.objective_range = mdp.horizon->value->range;
      auto value = expressions_.constant_integer(*mdp.horizon->value, "the horizon");
      if (value && (*value < 1 || *value > limits::kMaxHorizon)) {
        diagnostics_.error(mdp.horizon->value->range, "horizon must be between 1 and 10^9 steps");
      } else if (value) {
        ir_.objective.horizon = static_cast<std::uint32_t>(*value);
      }
    }
    check_abstraction_target(mdp);
    if (mdp.period) {
      auto value = expressions_.constant_number(*mdp.period->value, "the period");
      if (value && *value <= 0) {
        diagnostics_.error(mdp.period->value->range, "period must be positive (seconds per step)");
      } else if (value) {
        ir_.period = *value;
      }
    }
  }

  // `epsilon e;` and `max_cells n;`: the continuous abstraction's target and budget.
  void check_abstraction_target(const ast::MdpDecl& mdp) {
    for (const auto* setting : {&mdp.epsilon, &mdp.max_cells}) {
      if (*setting && ir_.kind != model::ModelKind::Continuous)
        diagnostics_.error((*setting)->range,
                           "'epsilon' and 'max_cells' set the abstraction of continuous "
                           "states; an explicit model's quotient is exact");
    }
    if (ir_.kind != model::ModelKind::Continuous) return;
    if (mdp.epsilon) {
      auto value = expressions_.constant_number(*mdp.epsilon->value, "epsilon");
      if (value && (*value <= 0 || *value > 1)) {
        diagnostics_.error(mdp.epsilon->value->range,
                           "epsilon bounds a total-variation distance: it must be in (0, 1], not " +
                               describe(*value));
      } else if (value) {
        ir_.epsilon = *value;
      }
    }
    if (mdp.max_cells) {
      auto value = expressions_.constant_integer(*mdp.max_cells->value, "max_cells");
      if (value && (*value < 1 || *value > limits::kMaxCellsSetting)) {
        diagnostics_.error(mdp.max_cells->value->range,
                           "max_cells must be between 1 and 10^8 cells per context");
      } else if (value) {
        ir_.max_cells = static_cast<std::uint64_t>(*value);
      }
    }
  }

  // The policy solver works in doubles (docs/policies.md): a discount must stay a discount
  // there, and 1 is allowed only with a finite horizon, where values stay finite.
  void check_discount(const ast::Expr& expr, bool has_horizon) {
    auto value = expressions_.constant_number(expr, "the discount");
    if (!value) return;
    if (*value <= 0 || *value > 1) {
      diagnostics_.error(expr.range, "discount must be in (0, 1], not " + describe(*value));
    } else if (*value == 1 && !has_horizon) {
      diagnostics_.error(expr.range,
                         "discount 1 over an infinite horizon may give infinite values: write a "
                         "discount below 1, or 'horizon N' for undiscounted rewards over N steps");
    } else if (*value < 1 && to_double(*value) == 1) {
      diagnostics_.error(expr.range, "discount 1 - " + describe(1 - *value) +
                                         " rounds to 1 in double precision, where the policy "
                                         "is solved; write at most 1 - 2^-53 (0.9999999999999999)");
    } else {
      ir_.objective.discount = *value;
    }
  }

  // ---- behaviour --------------------------------------------------------------------------

  LoweredBehaviour lower_behaviour(const ast::Behaviour& body, bool is_context) {
    LoweredBehaviour lowered;
    lowered.commands_by_action.resize(ir_.actions.size());
    lowered.overrides_action.assign(ir_.actions.size(), false);
    lowered.dynamics.resize(ir_.actions.size());
    for (const auto& transition : body.transitions)
      lower_explicit_transition(transition, lowered);
    for (const auto& command : body.commands)
      lower_command(command, lowered);
    for (const auto& reward : body.rewards) {
      lowered.has_rewards = true;
      if (auto lowered_reward = lower_reward(reward))
        lowered.rewards.push_back(std::move(*lowered_reward));
    }
    // Disturbances outside a dynamics block hold for every block of this body. They are
    // checked here, once: checked per block, a mistake in one was reported once per block,
    // and not at all when there was no block (or in a discrete model, which ignored them).
    std::vector<LoweredDisturbance> shared;
    if (ir_.kind != ModelKind::Continuous) {
      for (const auto& disturbance : body.disturbances) {
        diagnostics_.error(disturbance.range,
                           "disturbances belong to models with continuous variables");
      }
    } else if (!body.disturbances.empty() && body.dynamics.empty() && is_context) {
      diagnostics_.error(body.disturbances.front().range,
                         "a context's disturbance must sit inside its 'dynamics' blocks");
    } else {
      for (const auto& disturbance : body.disturbances) {
        if (auto checked = lower_disturbance(disturbance)) shared.push_back(*checked);
      }
    }
    if (!is_context) model_disturbances_ = shared;
    for (const auto& dynamics : body.dynamics)
      lower_dynamics(dynamics, shared, lowered);
    lowered.empty = body.transitions.empty() && body.commands.empty() && body.rewards.empty() &&
                    body.dynamics.empty() && body.disturbances.empty();
    return lowered;
  }

  void lower_explicit_transition(const ast::ExplicitTransition& transition,
                                 LoweredBehaviour& lowered) {
    if (ir_.kind != ModelKind::Explicit) {
      diagnostics_.error(transition.range,
                         "'state, action -> ...' transitions belong to models "
                         "that list their states; use '[action] guard -> ...'");
      return;
    }
    auto state = resolve_state(transition.state);
    auto action = resolve_action(transition.action);
    if (!state || !action) return;
    // The pair counts as given even when its distribution is rejected below, so that one
    // mistake does not also produce a "no transition" error.
    given_pairs_.insert({*state, *action});
    Command command;
    command.action = *action;
    command.range = transition.range;
    command.guard.op = Op::StateIs;
    command.guard.type = Type::Bool;
    command.guard.slot = *state;
    command.guard.range = transition.state.range;
    for (const ast::Branch& branch : transition.distribution.branches) {
      auto target = resolve_state(*branch.target);
      auto probability = branch_probability(branch);
      if (!target || !probability) return;
      model::Update update{0, Expression::make_constant(*target, Type::Int, branch.target->range),
                           branch.range};
      command.outcomes.push_back({std::move(*probability), {std::move(update)}, branch.range});
    }
    if (!check_distribution(command.outcomes, transition.distribution.range)) return;
    const auto key = std::make_pair(*state, *action);
    auto [it, inserted] = lowered.explicit_transitions.try_emplace(key, std::move(command));
    if (!inserted) {
      diagnostics_.error(transition.range, "state " + quoted(transition.state.text) +
                                               " already has a transition for action " +
                                               quoted(transition.action.text) +
                                               "; an MDP gives one distribution per action");
      diagnostics_.note(it->second.range, "the first transition is here");
    }
  }

  std::optional<Expression> branch_probability(const ast::Branch& branch) {
    if (!branch.probability) return Expression::make_constant(1, Type::Int, branch.range);
    const ExpressionRules rules{.discrete_state = ir_.kind == ModelKind::Factored,
                                .place = "in a probability"};
    return expressions_.check_typed(*branch.probability, rules, Type::Real, "a probability");
  }

  // Constant probabilities are checked here, exactly; state-dependent ones during exploration.
  bool check_distribution(const std::vector<model::Outcome>& outcomes, SourceRange whole) {
    Rational sum = 0;
    bool all_constant = true;
    bool ok = true;
    for (const model::Outcome& outcome : outcomes) {
      const Expression& p = outcome.probability;
      if (!p.is_constant()) {
        all_constant = false;
        continue;
      }
      if (p.constant < 0) {
        diagnostics_.error(p.range, "probability " + describe(p.constant) + " is negative");
        ok = false;
      } else if (p.constant > 1) {
        diagnostics_.error(p.range, "probability " + describe(p.constant) + " is greater than 1");
        ok = false;
      } else if (!check_carried_value(p.constant, "probability", p.range, diagnostics_)) {
        ok = false;
      }
      sum += p.constant;
    }
    if (ok && all_constant && sum != 1) {
      diagnostics_.error(whole, "probabilities sum to " + describe(sum) + ", not 1");
      ok = false;
    }
    return ok;
  }

  void lower_command(const ast::Command& command, LoweredBehaviour& lowered) {
    if (ir_.kind != ModelKind::Factored) {
      diagnostics_.error(command.range,
                         "'[action] guard -> ...' commands belong to models with "
                         "'var' variables");
      return;
    }
    auto action = resolve_action(command.action);
    const ExpressionRules rules{.discrete_state = true, .place = "in a guard"};
    auto guard = expressions_.check_typed(*command.guard, rules, Type::Bool, "a guard");
    if (!action || !guard) return;
    Command lowered_command{*action, std::move(*guard), {}, command.range};
    for (const ast::Branch& branch : command.distribution.branches) {
      auto probability = branch_probability(branch);
      auto updates = lower_updates(branch.updates);
      if (!probability || !updates) return;
      lowered_command.outcomes.push_back(
          {std::move(*probability), std::move(*updates), branch.range});
    }
    if (!check_distribution(lowered_command.outcomes, command.distribution.range)) return;
    lowered.overrides_action[*action] = true;
    lowered.commands_by_action[*action].push_back(std::move(lowered_command));
  }

  std::optional<std::vector<model::Update>> lower_updates(
      const std::vector<ast::Assignment>& updates) {
    std::vector<model::Update> lowered;
    std::vector<const ast::Assignment*> seen(ir_.variables.size(), nullptr);
    bool ok = true;
    for (const ast::Assignment& update : updates) {
      const auto* entry = scope_.find(update.variable.text);
      if (entry == nullptr || entry->value.kind != SymbolKind::Variable) {
        diagnostics_.error(update.variable.range,
                           (entry ? std::string(describe(entry->value.kind)) + " " +
                                        quoted(update.variable.text) + " cannot be updated"
                                  : "unknown variable " + quoted(update.variable.text)));
        ok = false;
        continue;
      }
      const std::uint32_t slot = entry->value.index;
      if (seen[slot] != nullptr) {
        diagnostics_.error(update.range, "variable " + quoted(update.variable.text) +
                                             " is updated twice in one outcome");
        diagnostics_.note(seen[slot]->range, "first update here");
        ok = false;
        continue;
      }
      seen[slot] = &update;
      const ExpressionRules rules{.discrete_state = true, .place = "in an update"};
      auto value = expressions_.check(*update.value, rules);
      if (!value) {
        ok = false;
        continue;
      }
      if (value->type != Type::Int) {
        diagnostics_.error(update.value->range, "integer variable " + quoted(update.variable.text) +
                                                    " needs an int, not a " +
                                                    std::string(model::describe(value->type)) +
                                                    " (round with floor() or ceil())");
        ok = false;
        continue;
      }
      check_constant_update_in_range(slot, *value);
      lowered.push_back({slot, std::move(*value), update.range});
    }
    if (!ok) return std::nullopt;
    return lowered;
  }

  // A constant assigned out of range is wrong in every state: say so now, not at exploration.
  void check_constant_update_in_range(std::uint32_t slot, const Expression& value) {
    if (!value.is_constant()) return;
    const model::DiscreteVariable& var = ir_.variables[slot];
    if (value.constant < var.low || value.constant > var.high) {
      diagnostics_.error(value.range, "value " + describe(value.constant) +
                                          " is outside the range [" + std::to_string(var.low) +
                                          " .. " + std::to_string(var.high) + "] of " +
                                          quoted(var.name));
    }
  }

  std::optional<model::Reward> lower_reward(const ast::RewardItem& item) {
    model::Reward reward;
    reward.range = item.range;
    if (item.action) {
      auto action = resolve_action(*item.action);
      if (!action) return std::nullopt;
      reward.action = *action;
    }
    const bool continuous = ir_.kind == ModelKind::Continuous;
    const ExpressionRules guard_rules{.discrete_state = !continuous,
                                      .continuous = continuous,
                                      .regions = continuous,
                                      .place = "in a reward condition"};
    auto guard =
        expressions_.check_typed(*item.guard, guard_rules, Type::Bool, "a reward condition");
    const ExpressionRules value_rules{.discrete_state = !continuous, .place = "in a reward value"};
    auto value = expressions_.check_typed(*item.value, value_rules, Type::Real, "a reward value");
    if (!guard || !value) return std::nullopt;
    // State-dependent values (and sums of several rewards) are checked during exploration.
    if (value->is_constant() &&
        !check_carried_value(value->constant, "reward", item.value->range, diagnostics_)) {
      return std::nullopt;
    }
    if (continuous && !model::polyhedral_constraints(*guard, ir_.continuous.size(), ir_.regions)) {
      diagnostics_.error(item.guard->range,
                         "a continuous reward condition must be a conjunction "
                         "of regions and linear inequalities");
      return std::nullopt;
    }
    reward.guard = std::move(*guard);
    reward.value = std::move(*value);
    return reward;
  }

  void lower_dynamics(const ast::Dynamics& dynamics, const std::vector<LoweredDisturbance>& shared,
                      LoweredBehaviour& lowered) {
    if (ir_.kind != ModelKind::Continuous) {
      diagnostics_.error(dynamics.range,
                         "'dynamics' blocks belong to models with continuous "
                         "variables");
      return;
    }
    auto action = resolve_action(dynamics.action);
    if (!action) return;
    if (lowered.dynamics[*action]) {
      diagnostics_.error(dynamics.range,
                         "action " + quoted(dynamics.action.text) + " already has dynamics here");
      diagnostics_.note(lowered.dynamics[*action]->range, "first dynamics here");
      return;
    }
    model::AffineDynamics affine = identity_dynamics(dynamics.range);
    std::vector<bool> assigned(ir_.continuous.size(), false);
    for (const ast::Assignment& equation : dynamics.equations) {
      if (!lower_equation(equation, affine, assigned)) return;
    }
    // The most specific disturbance wins: the block's own, then its body's (model or
    // context), then the model's, which holds for every action.
    for (const LoweredDisturbance& disturbance : shared) {
      affine.disturbance[disturbance.variable] = disturbance.model;
    }
    for (const auto& disturbance : dynamics.disturbances) {
      if (auto checked = lower_disturbance(disturbance)) {
        affine.disturbance[checked->variable] = checked->model;
      }
    }
    lowered.dynamics[*action] = std::move(affine);
  }

  bool lower_equation(const ast::Assignment& equation, model::AffineDynamics& affine,
                      std::vector<bool>& assigned) {
    const auto* entry = scope_.find(equation.variable.text);
    if (entry == nullptr || entry->value.kind != SymbolKind::ContinuousVariable) {
      diagnostics_.error(equation.variable.range,
                         "unknown continuous variable " + quoted(equation.variable.text));
      return false;
    }
    const std::uint32_t slot = entry->value.index;
    if (assigned[slot]) {
      diagnostics_.error(equation.range, "variable " + quoted(equation.variable.text) +
                                             " already has an equation in this block");
      return false;
    }
    assigned[slot] = true;
    const ExpressionRules rules{.continuous = true, .place = "in dynamics"};
    auto value = expressions_.check_typed(*equation.value, rules, Type::Real, "an equation");
    if (!value) return false;
    auto form = model::affine_form(*value, ir_.continuous.size());
    if (!form) {
      diagnostics_.error(equation.value->range,
                         "dynamics must be affine: a sum of constants "
                         "times variables, plus a constant");
      return false;
    }
    affine.matrix[slot] = std::move(form->coefficients);
    affine.offset[slot] = std::move(form->constant);
    return true;
  }

  std::optional<LoweredDisturbance> lower_disturbance(const ast::Disturbance& disturbance) {
    const auto* entry = scope_.find(disturbance.variable.text);
    if (entry == nullptr || entry->value.kind != SymbolKind::ContinuousVariable) {
      diagnostics_.error(disturbance.variable.range,
                         "unknown continuous variable " + quoted(disturbance.variable.text));
      return std::nullopt;
    }
    auto first = expressions_.constant_number(*disturbance.first,
                                              disturbance.gaussian ? "a mean" : "a bound");
    auto second = expressions_.constant_number(
        *disturbance.second, disturbance.gaussian ? "a standard deviation" : "a bound");
    if (!first || !second) return std::nullopt;
    if (disturbance.gaussian && *second <= 0) {
      diagnostics_.error(disturbance.second->range, "standard deviation must be positive");
      return std::nullopt;
    }
    if (!disturbance.gaussian && *first > *second) {
      diagnostics_.error(disturbance.range, "empty disturbance interval: " + describe(*first) +
                                                " is above " + describe(*second));
      return std::nullopt;
    }
    using Kind = model::DisturbanceModel::Kind;
    return LoweredDisturbance{
        entry->value.index,
        {disturbance.gaussian ? Kind::Gaussian : Kind::Bounded, *first, *second}};
  }

  // ---- completeness -----------------------------------------------------------------------

  void check_explicit_complete() {
    if (ir_.missing != model::MissingPolicy::Error) return;
    for (std::uint32_t s = 0; s < ir_.state_names.size() && !diagnostics_.should_stop(); ++s) {
      for (std::uint32_t a = 0; a < ir_.actions.size(); ++a) {
        if (given_pairs_.count({s, a}) != 0) continue;
        diagnostics_.error(state_ranges_[s], "state " + quoted(ir_.state_names[s]) +
                                                 " has no transition for action " +
                                                 quoted(ir_.actions[a]) +
                                                 " (add one, or write 'default self;' or "
                                                 "'default disabled;' in the model)");
        if (diagnostics_.should_stop()) return;
      }
    }
  }

  // x' = x (+ the model-level disturbances): the dynamics of an action that has no block.
  model::AffineDynamics identity_dynamics(SourceRange range) const {
    const std::size_t n = ir_.continuous.size();
    model::AffineDynamics affine;
    affine.range = range;
    affine.matrix.assign(n, std::vector<Rational>(n));
    affine.offset.assign(n, 0);
    affine.disturbance.assign(n, {});
    for (std::size_t i = 0; i < n; ++i)
      affine.matrix[i][i] = 1;
    for (const LoweredDisturbance& disturbance : model_disturbances_) {
      affine.disturbance[disturbance.variable] = disturbance.model;
    }
    return affine;
  }

  void check_dynamics_complete(const ast::MdpDecl& mdp) {
    if (ir_.missing == model::MissingPolicy::SelfLoop) {
      // `default self;`: an action without a block keeps the state, disturbed as every action.
      for (std::uint32_t a = 0; a < ir_.actions.size(); ++a) {
        if (!base_.dynamics[a]) base_.dynamics[a] = identity_dynamics(mdp.actions[a].range);
      }
      return;
    }
    if (ir_.missing != model::MissingPolicy::Error) return;
    for (std::uint32_t a = 0; a < ir_.actions.size(); ++a) {
      if (base_.dynamics[a]) continue;
      diagnostics_.error(mdp.actions[a].range, "action " + quoted(ir_.actions[a]) +
                                                   " has no 'dynamics' block (add one, or write "
                                                   "'default self;' for x' = x)");
    }
  }

  // ---- contexts and catalog ---------------------------------------------------------------

  // The command table of a behaviour layered over the base: explicit transitions replace the
  // base's for the same (state, action); factored commands replace all base commands of
  // their action.
  model::CommandTable build_table(const LoweredBehaviour& body, const model::CommandTable* base) {
    model::CommandTable table;
    table.by_action.resize(ir_.actions.size());
    if (base != nullptr) table = *base;
    for (const auto& [key, command] : body.explicit_transitions) {
      auto& commands = table.by_action[key.second];
      const std::uint32_t state = key.first;  // lambdas cannot capture structured bindings in C++17
      std::erase_if(commands, [state](const Command& c) { return c.guard.slot == state; });
      commands.push_back(command);
    }
    for (std::size_t a = 0; a < ir_.actions.size(); ++a) {
      if (body.overrides_action[a]) table.by_action[a] = body.commands_by_action[a];
    }
    return table;
  }

  model::ContextIR make_context(std::string name, SourceRange range, const LoweredBehaviour& body) {
    model::ContextIR context;
    context.name = std::move(name);
    context.range = range;
    const bool overrides_transitions =
        !body.explicit_transitions.empty() ||
        std::find(body.overrides_action.begin(), body.overrides_action.end(), true) !=
            body.overrides_action.end();
    if (overrides_transitions) {
      context.command_table = static_cast<std::uint32_t>(ir_.command_tables.size());
      ir_.command_tables.push_back(build_table(body, &ir_.command_tables.front()));
    }
    context.rewards = body.has_rewards ? body.rewards : base_.rewards;
    context.dynamics = base_.dynamics;
    for (std::size_t a = 0; a < body.dynamics.size(); ++a) {
      if (body.dynamics[a]) context.dynamics[a] = body.dynamics[a];
    }
    return context;
  }

  void check_catalog(const ast::MdpDecl& mdp) {
    ir_.command_tables.push_back(build_table(base_, nullptr));
    if (spec_.catalogs.empty()) {
      // The one context is the model as written, like `context default = base;`: it changes
      // nothing, so it uses the base table. (Passing `base_` as its body made a second,
      // identical table, and exploration stepped through every command twice.)
      ir_.contexts.push_back(make_context("default", mdp.name.range, LoweredBehaviour{}));
      ir_.switching.matrix = {Rational(1)};
      ir_.switching.prior = {Rational(1)};
      return;
    }
    const ast::CatalogDecl& catalog = spec_.catalogs.front();
    if (catalog.contexts.empty()) {
      diagnostics_.error(catalog.range, "catalog is empty: declare at least one 'context'");
      return;
    }
    if (catalog.contexts.size() > kMaxContexts) {
      diagnostics_.error(catalog.contexts[kMaxContexts].range,
                         "catalog has more than " + std::to_string(kMaxContexts) +
                             " contexts (the switching model alone would need N^2 entries)");
      return;
    }
    NameTable<std::uint32_t> names;
    for (const ast::ContextDecl& decl : catalog.contexts) {
      const auto index = static_cast<std::uint32_t>(ir_.contexts.size());
      if (!names.declare(decl.name.text, decl.name.range, index, "context", diagnostics_)) continue;
      LoweredBehaviour body = lower_behaviour(decl.behaviour, /*is_context=*/true);
      if (!decl.is_base && body.empty) {
        diagnostics_.error(decl.range, "context " + quoted(decl.name.text) +
                                           " is empty, so it names nothing to change; to use "
                                           "the base model as it is, write 'context " +
                                           std::string(decl.name.text) + " = base;'");
        continue;
      }
      ir_.contexts.push_back(make_context(std::string(decl.name.text), decl.range, body));
    }
    if (diagnostics_.has_errors()) return;
    check_switching_and_prior(catalog, names, ir_, diagnostics_, expressions_);
    if (catalog.observation)
      check_observation(*catalog.observation, scope_, ir_, diagnostics_, expressions_);
  }

  const ast::SpecFile& spec_;
  DiagnosticEngine& diagnostics_;
  Scope scope_;
  NameTable<model::ActionIndex> actions_;
  ExpressionChecker expressions_;
  model::ModelIR ir_;
  LoweredBehaviour base_;
  std::vector<SourceRange> state_ranges_;
  std::set<std::pair<std::uint32_t, std::uint32_t>> given_pairs_;  // base (state, action) pairs
  std::vector<LoweredDisturbance> model_disturbances_;  // model-level: hold for every action
};

}  // namespace

std::optional<model::ModelIR> check(const ast::SpecFile& spec, DiagnosticEngine& diagnostics,
                                    std::size_t max_number_bits) {
  return Checker(spec, diagnostics, max_number_bits).run();
}

}  // namespace oasis::frontend
