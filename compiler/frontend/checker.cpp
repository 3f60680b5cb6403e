#include "frontend/checker.hpp"

#include <algorithm>
#include <string>
#include <utility>

#include "frontend/behaviour_lowering.hpp"
#include "frontend/catalog_checker.hpp"
#include "frontend/expression_checker.hpp"
#include "frontend/guarantee_checker.hpp"
#include "frontend/import_checker.hpp"
#include "frontend/objective_checker.hpp"
#include "frontend/observation_checker.hpp"
#include "frontend/scope.hpp"
#include "model/affine.hpp"
#include "support/text.hpp"

namespace oasis::frontend {
namespace {

using model::Command;
using model::ModelKind;
using model::Type;

// support/limits.hpp says why each is what it is.
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
    declare_inputs(*mdp, ir_, scope_, expressions_, diagnostics_);
    declare_regions(*mdp);
    check_settings(*mdp);
    if (diagnostics_.has_errors()) return std::nullopt;  // names must be sound before bodies

    base_ = lowering_.lower_behaviour(mdp->behaviour, /*is_context=*/false);
    if (ir_.kind == ModelKind::Explicit) check_explicit_complete();
    if (ir_.kind == ModelKind::Continuous) check_dynamics_complete(*mdp);
    check_catalog(*mdp);
    check_guarantee(spec_, *mdp, ir_, scope_, expressions_, diagnostics_);
    if (diagnostics_.has_errors()) return std::nullopt;
    return std::move(ir_);
  }

 private:
  // ---- model-level declarations -----------------------------------------------------------

  const ast::MdpDecl* single_model() {
    if (spec_.mdps.empty()) {
      const FileId file = spec_.file;
      diagnostics_.error(SourceLocation{file, 0},
                         "spec declares no model: expected an 'mdp NAME { ... }' block or an "
                         "'import \"FILE\";'");
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
    for (const ast::ConstDecl& constant : mdp.constants)
      declare_constant(constant, scope_, expressions_, diagnostics_);
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
      if (auto state = lowering_.resolve_state(initial)) ir_.initial.push_back({*state});
    }
    if (ir_.initial.empty() && count > 0) ir_.initial.push_back({0});
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
      auto constraints =
          model::polyhedral_constraints(*condition, ir_.continuous.size(), ir_.regions);
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
    check_objective(mdp.discount, mdp.horizon, ir_, diagnostics_, expressions_);
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
  // ---- completeness -----------------------------------------------------------------------

  void check_explicit_complete() {
    if (ir_.missing != model::MissingPolicy::Error) return;
    for (std::uint32_t s = 0; s < ir_.state_names.size() && !diagnostics_.should_stop(); ++s) {
      for (std::uint32_t a = 0; a < ir_.actions.size(); ++a) {
        if (lowering_.has_transition(s, a)) continue;
        diagnostics_.error(state_ranges_[s], "state " + quoted(ir_.state_names[s]) +
                                                 " has no transition for action " +
                                                 quoted(ir_.actions[a]) +
                                                 " (add one, or write 'default self;' or "
                                                 "'default disabled;' in the model)");
        if (diagnostics_.should_stop()) return;
      }
    }
  }

  void check_dynamics_complete(const ast::MdpDecl& mdp) {
    if (ir_.missing == model::MissingPolicy::SelfLoop) {
      // `default self;`: an action without a block keeps the state, disturbed as every action.
      for (std::uint32_t a = 0; a < ir_.actions.size(); ++a) {
        if (!base_.maps[a]) base_.maps[a] = lowering_.identity_map(mdp.actions[a].range);
      }
      return;
    }
    if (ir_.missing != model::MissingPolicy::Error) return;
    for (std::uint32_t a = 0; a < ir_.actions.size(); ++a) {
      if (base_.maps[a]) continue;
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
    context.maps = base_.maps;
    for (std::size_t a = 0; a < body.maps.size(); ++a) {
      if (body.maps[a]) context.maps[a] = body.maps[a];
    }
    for (const auto& map : context.maps) {
      context.dynamics.push_back(map ? affine_dynamics(*map, ir_.continuous) : std::nullopt);
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
    if (!check_context_count(catalog, diagnostics_)) return;
    NameTable<std::uint32_t> names;
    for (const ast::ContextDecl& decl : catalog.contexts) {
      const auto index = static_cast<std::uint32_t>(ir_.contexts.size());
      if (!names.declare(decl.name.text, decl.name.range, index, "context", diagnostics_)) continue;
      if (decl.reward_structure) {
        diagnostics_.error(decl.reward_structure->range,
                           "'rewards \"NAME\"' takes a reward structure of an imported PRISM "
                           "program; this spec's model is written here, so give the context its "
                           "reward items: 'context " +
                               std::string(decl.name.text) + " { reward ...; }'");
        continue;
      }
      LoweredBehaviour body = lowering_.lower_behaviour(decl.behaviour, /*is_context=*/true);
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
    check_properties(catalog, !ir_.continuous.empty(), ir_, diagnostics_);
    if (catalog.observation)
      check_observation(*catalog.observation, scope_, ir_, diagnostics_, expressions_);
  }

  const ast::SpecFile& spec_;
  DiagnosticEngine& diagnostics_;
  Scope scope_;
  NameTable<model::ActionIndex> actions_;
  ExpressionChecker expressions_;
  model::ModelIR ir_;
  BehaviourLowering lowering_{ir_, scope_, actions_, expressions_, diagnostics_};
  LoweredBehaviour base_;
  std::vector<SourceRange> state_ranges_;
};

}  // namespace

std::optional<model::ModelIR> check(const ast::SpecFile& spec, DiagnosticEngine& diagnostics,
                                    std::size_t max_number_bits) {
  if (!spec.imports.empty()) return check_import_spec(spec, diagnostics, max_number_bits);
  return Checker(spec, diagnostics, max_number_bits).run();
}

}  // namespace oasis::frontend
