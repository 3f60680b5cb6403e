#include "pipeline/product_form.hpp"

#include <memory>
#include <numeric>

#include "bisim/discrete_proof.hpp"
#include "bisim/quotient.hpp"
#include "pipeline/stage_clock.hpp"
#include "policy/discounted_iteration.hpp"

namespace oasis::pipeline {
namespace {

using Clock = StageClock;

// Sweeps of the greedy policy alone between two full backups: each costs a sixth of a backup
// on the Go1 (one action of six), and 16 of them cut the backups from 370 to a few dozen.
constexpr std::uint32_t kEvaluationSweeps = 16;

// The compact rows as a context of policy/discounted_iteration.hpp: every action enabled,
// R(s, a) = R(s).
class ProductContext {
 public:
  explicit ProductContext(const CompactRows& rows) : rows_(rows) {
    reward_.resize(rows.num_states());
    for (std::uint32_t s = 0; s < rows.num_states(); ++s)
      reward_[s] = to_double(rows.values()[rows.state_reward(s)]);
  }

  [[nodiscard]] std::uint32_t num_states() const { return rows_.num_states(); }
  [[nodiscard]] std::uint32_t num_actions() const { return rows_.num_actions(); }
  [[nodiscard]] bool enabled(model::StateIndex /*s*/, model::ActionIndex /*a*/) const {
    return true;
  }
  [[nodiscard]] bool dead_end(model::StateIndex /*s*/) const { return false; }
  [[nodiscard]] double state_reward(model::StateIndex s) const { return reward_[s]; }
  [[nodiscard]] const std::vector<double>& rewards() const { return reward_; }
  void begin_sweep(const std::vector<double>& values) const { rows_.prepare(values.data()); }
  [[nodiscard]] double q_value(const std::vector<double>& values, model::StateIndex s,
                               model::ActionIndex a, double discount) const {
    return reward_[s] + discount * rows_.expectation(s, a, values.data());
  }

 private:
  const CompactRows& rows_;
  std::vector<double> reward_;
};

bisim::InvariantModel invariant_model(const CompactRows& rows, const std::vector<double>& reward) {
  bisim::InvariantModel model;
  model.num_states = rows.num_states();
  model.num_actions = rows.num_actions();
  model.reward = reward;
  model.prepare = [&rows](const double* x) { rows.prepare(x); };
  model.expectation = [&rows](std::uint32_t s, std::uint32_t a, const double* x) {
    return rows.expectation(s, a, x);
  };
  model.rounding_depth = rows.rounding_depth();
  model.smallest_term = rows.smallest_term();
  return model;
}

// The quotient when every state is its own block: the finite MDP's rewards, and its rows
// only when asked for (then materialised, and quotiented the usual way so that they read as
// any quotient's).
model::ExplicitModel discrete_quotient(const std::string& context, const CompactRows& rows,
                                       const model::ModelIR& ir, bool keep_rows) {
  if (keep_rows) {
    const model::ExplicitModel mdp = rows.materialise(context, ir.actions, ir.objective);
    model::Partition identity;
    identity.block_of.resize(mdp.num_states());
    std::iota(identity.block_of.begin(), identity.block_of.end(), 0U);
    identity.num_blocks = mdp.num_states();
    return bisim::build_quotient(mdp, 0, identity);
  }
  model::ExplicitModel quotient;
  quotient.name = context;
  quotient.actions = ir.actions;
  quotient.objective = ir.objective;
  quotient.states.size = rows.num_states();
  quotient.values = rows.values();
  model::RewardTable rewards;
  rewards.state.resize(rows.num_states());
  for (std::uint32_t s = 0; s < rows.num_states(); ++s)
    rewards.state[s] = rows.state_reward(s);
  model::TransitionBuilder no_rows(rows.num_states(), rows.num_actions());
  auto matrix = std::make_shared<const model::TransitionMatrix>(no_rows.finish(quotient.values));
  quotient.contexts.push_back({context, std::move(matrix), std::move(rewards)});
  return quotient;
}

}  // namespace

bool wants_product_form(std::size_t edges, const model::ModelIR& ir,
                        const ContinuousOptions& options) {
  if (options.grid_rows == GridRows::kMaterialised) return false;
  // Backward induction over a horizon stays with the materialised solver.
  if (policy::resolve_objective(ir.objective, options.policy).horizon) return false;
  switch (options.grid_rows) {
    case GridRows::kMaterialised:
      return false;
    case GridRows::kProduct:
      return true;
    case GridRows::kAutomatic:
      return edges > kProductRowsAbove;
  }
  return false;
}

ProductOutcome solve_in_product_form(const CompactRows& rows, const std::string& form,
                                     const model::ModelIR& ir, const ContinuousOptions& options,
                                     ContinuousAbstraction& result, std::string& error) {
  const auto report = [&](const std::string& done, double seconds) {
    if (options.progress) options.progress(result.context, done, seconds);
  };
  Clock::time_point start = Clock::now();
  const ProductContext context(rows);
  const bisim::DiscreteProof proof =
      bisim::prove_discrete(invariant_model(rows, context.rewards()));
  if (!proof.discrete) {
    report("the invariants tell " + std::to_string(proof.groups) + " groups of " +
               std::to_string(rows.num_states()) + " states apart in " +
               std::to_string(proof.rounds) + " rounds: exact refinement on materialised rows",
           seconds_since(start));
    return ProductOutcome::kNotDiscrete;
  }
  const std::uint32_t cells = rows.num_states() - 1;
  result.cell_block.resize(cells);
  std::iota(result.cell_block.begin(), result.cell_block.end(), 0U);
  result.outside_block = cells;
  result.num_blocks = rows.num_states();
  result.quotient = discrete_quotient(result.context, rows, ir, options.keep_rows);
  result.seconds.bisimulation = seconds_since(start);
  report("quotient, " + std::to_string(result.num_blocks) + " blocks (no two cells bisimilar: " +
             std::to_string(proof.rounds) + " rounds of invariants)",
         result.seconds.bisimulation);

  result.block_reward = context.rewards();
  const policy::ResolvedObjective objective =
      policy::resolve_objective(result.quotient, options.policy);
  const double threshold = policy::stopping_threshold(objective, options.policy.tolerance);
  std::uint32_t sweeps = 0;
  double residual = 0;
  if (!policy::modified_policy_iteration(context, objective.discount, threshold,
                                         options.policy.max_iterations, kEvaluationSweeps,
                                         result.value, sweeps, residual)) {
    error = "context '" + result.context + "': value iteration did not converge";
    return ProductOutcome::kFailed;
  }
  result.policy = policy::greedy_actions(context, result.value, objective.discount);
  result.seconds.policy = seconds_since(start);
  report("policy, " + std::to_string(sweeps) + " rounds of modified policy iteration (" +
             std::to_string(kEvaluationSweeps) + " evaluation sweeps each) on the " + form,
         result.seconds.policy);
  return ProductOutcome::kSolved;
}

}  // namespace oasis::pipeline
