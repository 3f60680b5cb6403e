#include "frontend/behaviour_lowering.hpp"

#include <string>

#include "model/affine.hpp"
#include "support/double_range.hpp"
#include "support/text.hpp"

namespace oasis::frontend {

using model::Command;
using model::Expression;
using model::ModelKind;
using model::Op;
using model::Type;

std::optional<std::uint32_t> BehaviourLowering::resolve_state(const ast::Name& name) {
  const auto* entry = scope_.find(name.text);
  if (entry == nullptr || entry->value.kind != SymbolKind::State) {
    diagnostics_.error(name.range, (entry ? std::string(describe(entry->value.kind)) + " "
                                          : std::string("unknown state ")) +
                                       quoted(name.text) + (entry ? " is not a state" : ""));
    return std::nullopt;
  }
  return entry->value.index;
}

std::optional<model::ActionIndex> BehaviourLowering::resolve_action(const ast::Name& name) {
  const auto* entry = actions_.find(name.text);
  if (entry == nullptr) {
    diagnostics_.error(name.range, "unknown action " + quoted(name.text));
    return std::nullopt;
  }
  return entry->value;
}

LoweredBehaviour BehaviourLowering::lower_behaviour(const ast::Behaviour& body, bool is_context) {
  LoweredBehaviour lowered;
  lowered.commands_by_action.resize(ir_.actions.size());
  lowered.overrides_action.assign(ir_.actions.size(), false);
  lowered.maps.resize(ir_.actions.size());
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

void BehaviourLowering::lower_explicit_transition(const ast::ExplicitTransition& transition,
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

std::optional<Expression> BehaviourLowering::branch_probability(const ast::Branch& branch) {
  if (!branch.probability) return Expression::make_constant(1, Type::Int, branch.range);
  const ExpressionRules rules{.discrete_state = ir_.kind == ModelKind::Factored,
                              .place = "in a probability"};
  return expressions_.check_typed(*branch.probability, rules, Type::Real, "a probability");
}

// Constant probabilities are checked here, exactly; state-dependent ones during exploration.
bool BehaviourLowering::check_distribution(const std::vector<model::Outcome>& outcomes,
                                           SourceRange whole) {
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

void BehaviourLowering::lower_command(const ast::Command& command, LoweredBehaviour& lowered) {
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

std::optional<std::vector<model::Update>> BehaviourLowering::lower_updates(
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
void BehaviourLowering::check_constant_update_in_range(std::uint32_t slot,
                                                       const Expression& value) {
  if (!value.is_constant()) return;
  const model::DiscreteVariable& var = ir_.variables[slot];
  if (value.constant < var.low || value.constant > var.high) {
    diagnostics_.error(value.range, "value " + describe(value.constant) +
                                        " is outside the range [" + std::to_string(var.low) +
                                        " .. " + std::to_string(var.high) + "] of " +
                                        quoted(var.name));
  }
}

std::optional<model::Reward> BehaviourLowering::lower_reward(const ast::RewardItem& item) {
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
  auto guard = expressions_.check_typed(*item.guard, guard_rules, Type::Bool, "a reward condition");
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

void BehaviourLowering::lower_dynamics(const ast::Dynamics& dynamics,
                                       const std::vector<LoweredDisturbance>& shared,
                                       LoweredBehaviour& lowered) {
  if (ir_.kind != ModelKind::Continuous) {
    diagnostics_.error(dynamics.range,
                       "'dynamics' blocks belong to models with continuous "
                       "variables");
    return;
  }
  auto action = resolve_action(dynamics.action);
  if (!action) return;
  if (lowered.maps[*action]) {
    diagnostics_.error(dynamics.range,
                       "action " + quoted(dynamics.action.text) + " already has dynamics here");
    diagnostics_.note(lowered.maps[*action]->range, "first dynamics here");
    return;
  }
  model::MapDynamics map = identity_map(dynamics.range);
  std::vector<bool> assigned(ir_.continuous.size(), false);
  for (const ast::Assignment& equation : dynamics.equations) {
    if (!lower_equation(equation, map, assigned)) return;
  }
  // The most specific disturbance wins: the block's own, then its body's (model or
  // context), then the model's, which holds for every action.
  for (const LoweredDisturbance& disturbance : shared) {
    map.disturbance[disturbance.variable] = disturbance.model;
  }
  for (const auto& disturbance : dynamics.disturbances) {
    if (auto checked = lower_disturbance(disturbance)) {
      map.disturbance[checked->variable] = checked->model;
    }
  }
  lowered.maps[*action] = std::move(map);
}

bool BehaviourLowering::lower_equation(const ast::Assignment& equation, model::MapDynamics& map,
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
  const ExpressionRules rules{.continuous = true, .dynamics = true, .place = "in dynamics"};
  auto value = expressions_.check_typed(*equation.value, rules, Type::Real, "an equation");
  if (!value) return false;
  map.next[slot] = std::move(*value);
  return true;
}

std::optional<LoweredDisturbance> BehaviourLowering::lower_disturbance(
    const ast::Disturbance& disturbance) {
  const auto* entry = scope_.find(disturbance.variable.text);
  if (entry == nullptr || entry->value.kind != SymbolKind::ContinuousVariable) {
    diagnostics_.error(disturbance.variable.range,
                       "unknown continuous variable " + quoted(disturbance.variable.text));
    return std::nullopt;
  }
  auto first =
      expressions_.constant_number(*disturbance.first, disturbance.gaussian ? "a mean" : "a bound");
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
      entry->value.index, {disturbance.gaussian ? Kind::Gaussian : Kind::Bounded, *first, *second}};
}

// x' = x (+ the model-level disturbances): the dynamics of an action that has no block.
model::MapDynamics BehaviourLowering::identity_map(SourceRange range) const {
  const std::size_t n = ir_.continuous.size();
  model::MapDynamics map;
  map.range = range;
  map.disturbance.assign(n, {});
  for (std::uint32_t i = 0; i < n; ++i) {
    model::Expression variable;
    variable.op = model::Op::ContinuousVariable;
    variable.type = Type::Real;
    variable.slot = i;
    variable.range = range;
    map.next.push_back(std::move(variable));
  }
  for (const LoweredDisturbance& disturbance : model_disturbances_) {
    map.disturbance[disturbance.variable] = disturbance.model;
  }
  return map;
}

namespace {

// A rational inside `c`, and how far the interval reaches from it. Never 0 for an interval that
// is not exactly 0: relevance (geom/relevance.hpp) reads the zero pattern of A, and a
// coefficient that may be nonzero must count as reading its variable.
std::pair<Rational, Rational> rounded(model::Interval c) {
  if (c.lo == 0 && c.hi == 0) return {Rational(0), Rational(0)};
  double middle = c.midpoint();
  if (middle == 0) middle = c.hi != 0 ? c.hi : c.lo;
  const Rational centre(middle);
  const Rational reach = std::max(Rational(c.hi) - centre, centre - Rational(c.lo));
  return {centre, reach};
}

// A component with irrational coefficients: rounded, with its error over the domain.
void round_component(const model::IntervalAffineForm& form,
                     const std::vector<model::ContinuousVariable>& variables,
                     model::AffineDynamics& affine, Rational& error) {
  std::vector<Rational> row;
  for (std::size_t j = 0; j < form.coefficients.size(); ++j) {
    auto [centre, reach] = rounded(form.coefficients[j]);
    row.push_back(centre);
    error += reach * std::max(abs(variables[j].low), abs(variables[j].high));
  }
  auto [offset, reach] = rounded(form.constant);
  error += reach;
  affine.matrix.push_back(std::move(row));
  affine.offset.push_back(std::move(offset));
}

}  // namespace

std::optional<model::AffineDynamics> affine_dynamics(
    const model::MapDynamics& map, const std::vector<model::ContinuousVariable>& variables) {
  const std::size_t n = map.next.size();
  model::AffineDynamics affine;
  affine.range = map.range;
  affine.disturbance = map.disturbance;
  std::vector<Rational> approximation(n);
  bool exact = true;
  for (std::size_t i = 0; i < n; ++i) {
    if (auto form = model::affine_form(map.next[i], n)) {
      affine.matrix.push_back(std::move(form->coefficients));
      affine.offset.push_back(std::move(form->constant));
      continue;
    }
    auto form = model::interval_affine_form(map.next[i], n);
    if (!form) return std::nullopt;
    round_component(*form, variables, affine, approximation[i]);
    exact = false;
  }
  if (!exact) affine.approximation = std::move(approximation);
  return affine;
}

}  // namespace oasis::frontend
