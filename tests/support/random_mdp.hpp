#pragma once
// Seeded random MDPs for property tests of bisimulation. Pure random models rarely have two
// equivalent states, so most models are built around a planted block structure: states of a
// planted block copy one block-level behaviour, each through its own choice of target states
// in the target blocks. Probabilities have small denominators and rewards come from a tiny
// set, so that different states often have equal sums and the coarsest bisimulation is
// coarser than the planted one. Some states are then rewritten at random to break the plant.

#include <algorithm>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "model/explicit_model.hpp"
#include "oasis/rt/split_mix64.hpp"

namespace oasis::test {

// The runtime's SplitMix64: the same sequence on every platform and standard library, unlike the
// distributions of <random>.
class TestRandom {
 public:
  explicit TestRandom(std::uint64_t seed) : bits_(seed) {}

  std::uint64_t next() { return bits_.next(); }
  // Uniform in [0, bound); bound > 0. The modulo bias is irrelevant here.
  std::uint32_t below(std::uint32_t bound) { return static_cast<std::uint32_t>(next() % bound); }
  // Uniform in [low, high].
  std::uint32_t between(std::uint32_t low, std::uint32_t high) {
    return low + below(high - low + 1);
  }
  // True with probability numerator / denominator.
  bool chance(std::uint32_t numerator, std::uint32_t denominator) {
    return below(denominator) < numerator;
  }
  template <typename T>
  const T& pick(const std::vector<T>& items) {
    return items[below(static_cast<std::uint32_t>(items.size()))];
  }

 private:
  rt::SplitMix64 bits_;
};

struct RandomMdpOptions {
  std::uint32_t max_states = 40;
  std::uint32_t max_actions = 4;
  std::uint32_t max_contexts = 3;
};

namespace random_mdp_detail {

using model::ActionIndex;
using model::StateIndex;

// `total` split into `count` positive parts whose denominators divide a small number.
inline std::vector<Rational> split(TestRandom& random, const Rational& total, std::uint32_t count) {
  static const std::vector<std::uint32_t> kDenominators{1, 2, 3, 4, 6, 8};
  std::uint32_t units = 0;
  do {
    units = random.pick(kDenominators);
  } while (units < count);
  // A random composition of `units` into `count` positive parts.
  std::vector<std::uint32_t> cuts;
  for (std::uint32_t c = 1; c < units; ++c)
    cuts.push_back(c);
  for (std::uint32_t i = 0; i + 1 < cuts.size(); ++i) {
    std::swap(cuts[i], cuts[i + random.below(static_cast<std::uint32_t>(cuts.size()) - i)]);
  }
  cuts.resize(count - 1);
  cuts.push_back(0);
  cuts.push_back(units);
  std::sort(cuts.begin(), cuts.end());
  std::vector<Rational> parts;
  for (std::uint32_t i = 0; i < count; ++i) {
    Rational part(cuts[i + 1] - cuts[i], units);
    part.canonicalize();  // gmpxx does not, and equal values must compare and hash equal
    parts.push_back(total * part);
  }
  return parts;
}

// `count` distinct items of `items` (count <= items.size()).
inline std::vector<StateIndex> choose(TestRandom& random, std::vector<StateIndex> items,
                                      std::uint32_t count) {
  for (std::uint32_t i = 0; i < count; ++i) {
    std::swap(items[i], items[i + random.below(static_cast<std::uint32_t>(items.size()) - i)]);
  }
  items.resize(count);
  return items;
}

inline Rational small_reward(TestRandom& random) {
  static const std::vector<Rational> kRewards{Rational(0), Rational(1, 2), Rational(1)};
  return random.pick(kRewards);
}

// The behaviour of one state or planted block: per action, nothing when disabled, else a
// distribution over targets (states or blocks), and the rewards.
struct Behaviour {
  std::vector<std::vector<std::pair<StateIndex, Rational>>> distribution;  // empty: disabled
  Rational state_reward;
  std::vector<Rational> choice_reward;
};

inline Behaviour random_behaviour(TestRandom& random, std::uint32_t num_targets,
                                  std::uint32_t num_actions, std::uint32_t enabled_percent,
                                  bool state_rewards, bool choice_rewards) {
  Behaviour behaviour;
  behaviour.distribution.resize(num_actions);
  behaviour.state_reward = state_rewards ? small_reward(random) : Rational(0);
  behaviour.choice_reward.assign(num_actions, Rational(0));
  std::vector<StateIndex> all(num_targets);
  for (StateIndex t = 0; t < num_targets; ++t)
    all[t] = t;
  for (ActionIndex a = 0; a < num_actions; ++a) {
    // Rewards of disabled choices too: the engine must ignore them.
    if (choice_rewards) behaviour.choice_reward[a] = small_reward(random);
    if (!random.chance(enabled_percent, 100)) continue;
    const std::uint32_t count = random.between(1, std::min<std::uint32_t>(4, num_targets));
    const std::vector<StateIndex> targets = choose(random, all, count);
    const std::vector<Rational> probabilities = split(random, Rational(1), count);
    for (std::uint32_t i = 0; i < count; ++i) {
      behaviour.distribution[a].emplace_back(targets[i], probabilities[i]);
    }
  }
  return behaviour;
}

struct GeneratedContext {
  std::shared_ptr<const model::TransitionMatrix> transitions;
  model::RewardTable rewards;
  std::vector<std::uint32_t> planted;  // planted block of each state
  std::vector<Behaviour> block_behaviour;
};

inline model::RewardTable make_rewards(TestRandom& random,
                                       const std::vector<std::uint32_t>& planted,
                                       const std::vector<Behaviour>& block_behaviour,
                                       std::uint32_t num_actions, bool choice_rewards,
                                       RationalPool& values) {
  const auto n = static_cast<std::uint32_t>(planted.size());
  model::RewardTable table;
  table.state.assign(n, RationalPool::kZero);
  if (choice_rewards) table.choice.assign(std::size_t{n} * num_actions, RationalPool::kZero);
  for (StateIndex s = 0; s < n; ++s) {
    const Behaviour& block = block_behaviour[planted[s]];
    // R(s, a) = state + choice is what must agree, not the parts: move some reward between
    // them.
    Rational shift = 0;
    if (choice_rewards && random.chance(1, 3))
      shift = random.chance(1, 2) ? Rational(1, 2) : Rational(-1, 2);
    table.state[s] = values.intern(block.state_reward + shift);
    for (ActionIndex a = 0; a < num_actions && choice_rewards; ++a) {
      table.choice[s * num_actions + a] = values.intern(block.choice_reward[a] - shift);
    }
  }
  return table;
}

inline GeneratedContext generate_context(TestRandom& random, std::uint32_t n,
                                         std::uint32_t num_actions, RationalPool& values) {
  GeneratedContext context;
  const std::uint32_t enabled_percent = random.pick(std::vector<std::uint32_t>{50, 80, 100});
  const std::uint32_t reward_kind = random.below(3);  // state, choice, both
  const bool state_rewards = reward_kind != 1;
  const bool choice_rewards = reward_kind != 0;

  // Planted blocks: few, so that they are large; every block non-empty.
  const std::uint32_t m =
      random.chance(1, 5) ? n : random.between(1, std::max<std::uint32_t>(1, n / 3));
  std::vector<StateIndex> order(n);
  for (StateIndex s = 0; s < n; ++s)
    order[s] = s;
  order = choose(random, order, n);
  context.planted.resize(n);
  std::vector<std::vector<StateIndex>> members(m);
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t block = i < m ? i : random.below(m);
    context.planted[order[i]] = block;
    members[block].push_back(order[i]);
  }
  for (std::uint32_t b = 0; b < m; ++b) {
    context.block_behaviour.push_back(
        random_behaviour(random, m, num_actions, enabled_percent, state_rewards, choice_rewards));
  }

  // Each state realises its block's distribution over blocks with its own targets.
  model::TransitionBuilder builder(n, num_actions);
  for (StateIndex s = 0; s < n; ++s) {
    const Behaviour& block = context.block_behaviour[context.planted[s]];
    for (ActionIndex a = 0; a < num_actions; ++a) {
      for (const auto& [target_block, p] : block.distribution[a]) {
        const auto& candidates = members[target_block];
        const std::uint32_t count = random.between(
            1, std::min<std::uint32_t>(2, static_cast<std::uint32_t>(candidates.size())));
        const std::vector<StateIndex> targets = choose(random, candidates, count);
        const std::vector<Rational> parts = split(random, p, count);
        for (std::uint32_t i = 0; i < count; ++i)
          builder.add(s, a, targets[i], values.intern(parts[i]));
      }
    }
  }
  context.rewards = make_rewards(random, context.planted, context.block_behaviour, num_actions,
                                 choice_rewards, values);

  // Break the plant: a few states get a fresh random behaviour, in transitions or rewards.
  model::TransitionMatrix matrix = builder.finish(values);
  const std::uint32_t rewritten = random.chance(1, 2) ? 0 : random.between(1, 3);
  for (std::uint32_t i = 0; i < rewritten; ++i) {
    const StateIndex s = random.below(n);
    if (random.chance(1, 2)) {
      const ActionIndex a = random.below(num_actions);
      if (!context.rewards.choice.empty()) {
        context.rewards.choice[s * num_actions + a] = values.intern(small_reward(random));
      } else {
        context.rewards.state[s] = values.intern(small_reward(random));
      }
      continue;
    }
    const Behaviour fresh = random_behaviour(random, n, num_actions, enabled_percent, false, false);
    model::TransitionBuilder rebuilt(n, num_actions);
    for (StateIndex t = 0; t < n; ++t) {
      for (ActionIndex a = 0; a < num_actions; ++a) {
        if (t == s) {
          for (const auto& [target, p] : fresh.distribution[a])
            rebuilt.add(t, a, target, values.intern(p));
          continue;
        }
        for (model::EdgeIndex e = matrix.edges_begin(t, a); e < matrix.edges_end(t, a); ++e) {
          rebuilt.add(t, a, matrix.edge_target[e], matrix.edge_probability[e]);
        }
      }
    }
    matrix = rebuilt.finish(values);
  }
  context.transitions = std::make_shared<const model::TransitionMatrix>(std::move(matrix));
  return context;
}

}  // namespace random_mdp_detail

// A random model with 1..max_states states, 1..max_actions actions and 1..max_contexts
// contexts; the same seed gives the same model. Later contexts sometimes share the first
// one's transitions and differ only in rewards. States are named "s0", "s1", ..., by a
// variable ("(x=3)") or not at all, at random.
inline model::ExplicitModel random_mdp(std::uint64_t seed, const RandomMdpOptions& options = {}) {
  using namespace random_mdp_detail;
  TestRandom random(seed);
  model::ExplicitModel model;
  model.name = "random_" + std::to_string(seed);
  const std::uint32_t n = random.between(1, options.max_states);
  const std::uint32_t k = random.between(1, options.max_actions);
  model.states.size = n;
  switch (random.below(3)) {
    case 0:
      for (StateIndex s = 0; s < n; ++s)
        model.states.names.push_back("s" + std::to_string(s));
      break;
    case 1:
      model.states.variables = {"x"};
      for (StateIndex s = 0; s < n; ++s)
        model.states.valuations.push_back(s);
      break;
    default:
      break;
  }
  model.states.initial = {0};
  for (ActionIndex a = 0; a < k; ++a)
    model.actions.push_back("a" + std::to_string(a));

  const std::uint32_t num_contexts =
      random.chance(2, 3) ? 1 : random.between(2, options.max_contexts);
  GeneratedContext first;
  for (std::uint32_t c = 0; c < num_contexts; ++c) {
    GeneratedContext generated;
    if (c > 0 && random.chance(1, 2)) {
      // Same transitions, rewards drawn afresh per planted block of the first context.
      generated.transitions = first.transitions;
      generated.planted = first.planted;
      generated.block_behaviour = first.block_behaviour;
      const bool choice_rewards = random.chance(1, 2);
      for (Behaviour& behaviour : generated.block_behaviour) {
        behaviour.state_reward = small_reward(random);
        for (Rational& r : behaviour.choice_reward)
          r = choice_rewards ? small_reward(random) : Rational(0);
      }
      generated.rewards = make_rewards(random, generated.planted, generated.block_behaviour, k,
                                       choice_rewards, model.values);
    } else {
      generated = generate_context(random, n, k, model.values);
    }
    if (c == 0) first = generated;
    model.contexts.push_back(
        {"context" + std::to_string(c), generated.transitions, std::move(generated.rewards)});
  }
  return model;
}

}  // namespace oasis::test
