#pragma once
// Lowering the body of the model or of one context (explicit transitions, guarded commands,
// rewards, dynamics and disturbances) into the IR's commands, rewards and affine dynamics,
// with the checks that belong to each. The checker (checker.cpp) declares the names first;
// this reads them, and the IR's kind and variables, and never changes the IR.

#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <utility>
#include <vector>

#include "frontend/ast.hpp"
#include "frontend/expression_checker.hpp"
#include "frontend/scope.hpp"
#include "model/model_ir.hpp"
#include "support/diagnostics.hpp"

namespace oasis::frontend {

// The affine form of a map (x' = A x + b), when every component is affine in the continuous
// variables and reads no input; nullopt otherwise. Coefficients that are irrational constants
// (cos(0.1)) are rounded to rationals, with the error this makes over the domain `variables`
// in AffineDynamics::approximation.
std::optional<model::AffineDynamics> affine_dynamics(
    const model::MapDynamics& map, const std::vector<model::ContinuousVariable>& variables);

// Everything a model or context body says, lowered. `transitions` is per (state, action)
// for explicit models and per action for factored ones.
struct LoweredBehaviour {
  std::vector<std::vector<model::Command>> commands_by_action;
  std::vector<bool> overrides_action;  // factored: this body gives commands for the action
  std::map<std::pair<std::uint32_t, std::uint32_t>, model::Command> explicit_transitions;
  std::vector<model::Reward> rewards;
  bool has_rewards = false;
  std::vector<std::optional<model::MapDynamics>> maps;  // per action: its `dynamics` block
  bool empty = true;
};

// A checked `disturbance` item: the continuous variable it acts on, and how.
struct LoweredDisturbance {
  std::uint32_t variable = 0;
  model::DisturbanceModel model;
};

class BehaviourLowering {
 public:
  BehaviourLowering(const model::ModelIR& ir, const Scope& scope,
                    const NameTable<model::ActionIndex>& actions, ExpressionChecker& expressions,
                    DiagnosticEngine& diagnostics)
      : ir_(ir),
        scope_(scope),
        actions_(actions),
        expressions_(expressions),
        diagnostics_(diagnostics) {}

  // The model's body (`is_context` false; its disturbances then hold for every action) or a
  // context's.
  LoweredBehaviour lower_behaviour(const ast::Behaviour& body, bool is_context);

  // A declared state or action by name; nullopt, with an error, when there is none.
  std::optional<std::uint32_t> resolve_state(const ast::Name& name);
  std::optional<model::ActionIndex> resolve_action(const ast::Name& name);

  // x' = x (+ the model-level disturbances): the dynamics of an action that has no block.
  [[nodiscard]] model::MapDynamics identity_map(SourceRange range) const;

  // Whether some body gave an explicit transition for (state, action), even one whose
  // distribution was refused: one mistake should not also produce a "no transition" error.
  [[nodiscard]] bool has_transition(std::uint32_t state, std::uint32_t action) const {
    return given_pairs_.count({state, action}) != 0;
  }

 private:
  void lower_explicit_transition(const ast::ExplicitTransition& transition,
                                 LoweredBehaviour& lowered);
  std::optional<model::Expression> branch_probability(const ast::Branch& branch);
  // Constant probabilities are checked here, exactly; state-dependent ones during exploration.
  bool check_distribution(const std::vector<model::Outcome>& outcomes, SourceRange whole);
  void lower_command(const ast::Command& command, LoweredBehaviour& lowered);
  std::optional<std::vector<model::Update>> lower_updates(
      const std::vector<ast::Assignment>& updates);
  // A constant assigned out of range is wrong in every state: say so now, not at exploration.
  void check_constant_update_in_range(std::uint32_t slot, const model::Expression& value);
  std::optional<model::Reward> lower_reward(const ast::RewardItem& item);
  void lower_dynamics(const ast::Dynamics& dynamics, const std::vector<LoweredDisturbance>& shared,
                      LoweredBehaviour& lowered);
  bool lower_equation(const ast::Assignment& equation, model::MapDynamics& map,
                      std::vector<bool>& assigned);
  std::optional<LoweredDisturbance> lower_disturbance(const ast::Disturbance& disturbance);

  const model::ModelIR& ir_;
  const Scope& scope_;
  const NameTable<model::ActionIndex>& actions_;
  ExpressionChecker& expressions_;
  DiagnosticEngine& diagnostics_;
  std::set<std::pair<std::uint32_t, std::uint32_t>> given_pairs_;
  std::vector<LoweredDisturbance> model_disturbances_;  // model-level: hold for every action
};

}  // namespace oasis::frontend
