#pragma once
// Models and references for the model checker's tests: small MDPs written edge by edge, the
// seeded random MDPs of tests/support/random_mdp.hpp, and a naive reference that owes nothing
// to the engine: Markov chains solved by dense Gauss-Jordan elimination over rationals after a
// plain fixpoint reachability search, and MDP optima by enumerating every memoryless
// deterministic scheduler (which suffice for reachability and expected total rewards).

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "../../support/random_mdp.hpp"
#include "model/explicit_model.hpp"
#include "modelcheck/engine.hpp"

namespace oasis::test {

using model::ActionIndex;
using model::StateIndex;
using modelcheck::Optimum;
using modelcheck::StateSet;

struct HandEdge {
  StateIndex from;
  ActionIndex action;
  StateIndex to;
  Rational probability;
};

struct CheckModel {
  RationalPool values;
  model::TransitionMatrix matrix;
  model::RewardTable rewards;

  [[nodiscard]] modelcheck::Problem problem(Optimum optimum) const {
    return {matrix, values, optimum};
  }
};

inline CheckModel hand_model(std::uint32_t num_states, std::uint32_t num_actions,
                             const std::vector<HandEdge>& edges,
                             const std::vector<Rational>& state_rewards = {},
                             const std::vector<Rational>& choice_rewards = {}) {
  CheckModel m;
  model::TransitionBuilder builder(num_states, num_actions);
  for (const HandEdge& e : edges)
    builder.add(e.from, e.action, e.to, m.values.intern(e.probability));
  m.matrix = builder.finish(m.values);
  for (const Rational& r : state_rewards)
    m.rewards.state.push_back(m.values.intern(r));
  for (const Rational& r : choice_rewards)
    m.rewards.choice.push_back(m.values.intern(r));
  return m;
}

inline CheckModel random_check_model(std::uint64_t seed, std::uint32_t max_states,
                                     std::uint32_t max_actions) {
  model::ExplicitModel generated =
      random_mdp(seed, RandomMdpOptions{max_states, max_actions, 2});  // context 0 is used
  CheckModel m;
  m.values = std::move(generated.values);
  m.matrix = *generated.contexts[0].transitions;
  m.rewards = std::move(generated.contexts[0].rewards);
  // The generator moves reward between R(s) and R(s, a) with either sign; the reward operators
  // need R(s, a) >= 0 everywhere, also where a state has no action and earns R(s) alone.
  for (ValueId& r : m.rewards.state)
    r = m.values.intern(abs(m.values[r]));
  for (ValueId& r : m.rewards.choice)
    r = m.values.intern(abs(m.values[r]));
  return m;
}

inline StateSet random_set(TestRandom& random, std::uint32_t n, std::uint32_t percent) {
  StateSet set(n);
  for (std::uint32_t s = 0; s < n; ++s)
    set[s] = random.chance(percent, 100);
  return set;
}

// --- The naive reference -------------------------------------------------------------------

// The successors of s under action a, PRISM's self-loop for a state with no enabled action, and
// the first enabled action for kAnyAction.
inline std::vector<std::pair<StateIndex, Rational>> successors(const CheckModel& m, StateIndex s,
                                                               ActionIndex a) {
  if (a == modelcheck::Scheduler::kAnyAction) {
    for (a = 0; a < m.matrix.num_actions && !m.matrix.enabled(s, a); ++a) {
    }
  }
  if (a >= m.matrix.num_actions) return {{s, Rational(1)}};
  std::vector<std::pair<StateIndex, Rational>> next;
  for (auto e = m.matrix.edges_begin(s, a); e < m.matrix.edges_end(s, a); ++e)
    next.emplace_back(m.matrix.edge_target[e], m.values[m.matrix.edge_probability[e]]);
  return next;
}

inline Rational reward_of(const CheckModel& m, StateIndex s, ActionIndex a) {
  Rational r = m.rewards.state.empty() ? Rational(0) : m.values[m.rewards.state[s]];
  if (a == modelcheck::Scheduler::kAnyAction) {
    for (a = 0; a < m.matrix.num_actions && !m.matrix.enabled(s, a); ++a) {
    }
  }
  if (a < m.matrix.num_actions && !m.rewards.choice.empty())
    r += m.values[m.rewards.choice[m.matrix.choice(s, a)]];
  return r;
}

// Solves x_i - sum_j a[i][j] x_j = b_i (dense, Gauss-Jordan with rational pivots).
inline std::vector<Rational> dense_solve(std::vector<std::vector<Rational>> a,
                                         std::vector<Rational> b) {
  const std::size_t n = b.size();
  std::vector<std::vector<Rational>> m(n, std::vector<Rational>(n + 1));
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j)
      m[i][j] = (i == j ? Rational(1) : Rational(0)) - a[i][j];
    m[i][n] = b[i];
  }
  for (std::size_t col = 0; col < n; ++col) {
    std::size_t pivot = col;
    while (m[pivot][col] == 0)
      ++pivot;
    std::swap(m[pivot], m[col]);
    const Rational inverse = 1 / m[col][col];
    for (auto& v : m[col])
      v *= inverse;
    for (std::size_t i = 0; i < n; ++i) {
      if (i == col || m[i][col] == 0) continue;
      const Rational factor = m[i][col];
      for (std::size_t j = col; j <= n; ++j)
        m[i][j] -= factor * m[col][j];
    }
  }
  std::vector<Rational> x(n);
  for (std::size_t i = 0; i < n; ++i)
    x[i] = m[i][n];
  return x;
}

// P(phi U psi) in the chain that takes action[s] in s.
inline std::vector<Rational> naive_until(const CheckModel& m,
                                         const std::vector<ActionIndex>& action,
                                         const StateSet& phi, const StateSet& psi) {
  const std::uint32_t n = m.matrix.num_states;
  StateSet reach = psi;
  for (bool grew = true; grew;) {
    grew = false;
    for (StateIndex s = 0; s < n; ++s) {
      if (reach[s] || !phi[s]) continue;
      for (const auto& [t, p] : successors(m, s, action[s])) {
        if (reach[t]) {
          reach[s] = true;
          grew = true;
          break;
        }
      }
    }
  }
  std::vector<StateIndex> unknown;
  std::vector<std::int64_t> index(n, -1);
  for (StateIndex s = 0; s < n; ++s) {
    if (reach[s] && !psi[s]) {
      index[s] = static_cast<std::int64_t>(unknown.size());
      unknown.push_back(s);
    }
  }
  std::vector<std::vector<Rational>> a(unknown.size(), std::vector<Rational>(unknown.size()));
  std::vector<Rational> b(unknown.size());
  for (std::size_t i = 0; i < unknown.size(); ++i) {
    for (const auto& [t, p] : successors(m, unknown[i], action[unknown[i]])) {
      if (psi[t]) b[i] += p;
      if (index[t] >= 0) a[i][index[t]] += p;
    }
  }
  const std::vector<Rational> solved = dense_solve(a, b);
  std::vector<Rational> x(n);
  for (StateIndex s = 0; s < n; ++s)
    x[s] = psi[s] ? Rational(1) : index[s] >= 0 ? solved[index[s]] : Rational(0);
  return x;
}

// The expected reward before `target` in the chain; nullopt for infinity.
inline std::vector<std::optional<Rational>> naive_reward(const CheckModel& m,
                                                         const std::vector<ActionIndex>& action,
                                                         const StateSet& target) {
  const std::uint32_t n = m.matrix.num_states;
  const std::vector<Rational> reach = naive_until(m, action, StateSet(n, true), target);
  std::vector<StateIndex> unknown;
  std::vector<std::int64_t> index(n, -1);
  for (StateIndex s = 0; s < n; ++s) {
    if (reach[s] == 1 && !target[s]) {
      index[s] = static_cast<std::int64_t>(unknown.size());
      unknown.push_back(s);
    }
  }
  std::vector<std::vector<Rational>> a(unknown.size(), std::vector<Rational>(unknown.size()));
  std::vector<Rational> b(unknown.size());
  for (std::size_t i = 0; i < unknown.size(); ++i) {
    b[i] = reward_of(m, unknown[i], action[unknown[i]]);
    for (const auto& [t, p] : successors(m, unknown[i], action[unknown[i]])) {
      if (index[t] >= 0) a[i][index[t]] += p;
    }
  }
  const std::vector<Rational> solved = dense_solve(a, b);
  std::vector<std::optional<Rational>> x(n);
  for (StateIndex s = 0; s < n; ++s) {
    if (target[s]) {
      x[s] = Rational(0);
    } else if (index[s] >= 0) {
      x[s] = solved[index[s]];
    }
  }
  return x;
}

// Calls visit(action) for every memoryless deterministic scheduler.
template <typename Visit>
void for_each_scheduler(const CheckModel& m, Visit visit) {
  const std::uint32_t n = m.matrix.num_states;
  std::vector<std::vector<ActionIndex>> options(n);
  for (StateIndex s = 0; s < n; ++s) {
    for (ActionIndex a = 0; a < m.matrix.num_actions; ++a) {
      if (m.matrix.enabled(s, a)) options[s].push_back(a);
    }
    if (options[s].empty()) options[s].push_back(modelcheck::Scheduler::kAnyAction);
  }
  std::vector<std::size_t> digit(n, 0);
  std::vector<ActionIndex> action(n);
  for (;;) {
    for (StateIndex s = 0; s < n; ++s)
      action[s] = options[s][digit[s]];
    visit(action);
    StateIndex s = 0;
    while (s < n && ++digit[s] == options[s].size())
      digit[s++] = 0;
    if (s == n) return;
  }
}

inline bool better(Optimum optimum, const std::optional<Rational>& a,
                   const std::optional<Rational>& b) {
  // nullopt is +infinity.
  if (optimum == Optimum::kMax) return a.has_value() ? (b.has_value() && *a > *b) : b.has_value();
  return a.has_value() && (!b.has_value() || *a < *b);
}

inline std::vector<Rational> brute_force_until(const CheckModel& m, Optimum optimum,
                                               const StateSet& phi, const StateSet& psi) {
  std::vector<Rational> best;
  for_each_scheduler(m, [&](const std::vector<ActionIndex>& action) {
    const std::vector<Rational> x = naive_until(m, action, phi, psi);
    if (best.empty()) {
      best = x;
      return;
    }
    for (std::size_t s = 0; s < x.size(); ++s) {
      if (better(optimum, x[s], best[s])) best[s] = x[s];
    }
  });
  return best;
}

inline std::vector<std::optional<Rational>> brute_force_reward(const CheckModel& m, Optimum optimum,
                                                               const StateSet& target) {
  std::vector<std::optional<Rational>> best;
  bool first = true;
  for_each_scheduler(m, [&](const std::vector<ActionIndex>& action) {
    const std::vector<std::optional<Rational>> x = naive_reward(m, action, target);
    if (first) {
      best = x;
      first = false;
      return;
    }
    for (std::size_t s = 0; s < x.size(); ++s) {
      if (better(optimum, x[s], best[s])) best[s] = x[s];
    }
  });
  return best;
}

}  // namespace oasis::test
