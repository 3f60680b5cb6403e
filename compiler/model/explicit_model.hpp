#pragma once
// The explicit model: the IR every algorithm reads. One state space and action set shared by
// all contexts of a catalog; per context a sparse transition function in CSR arrays with
// 32-bit indices, and rewards. Probabilities and rewards are exact rationals, stored once in a
// RationalPool and referred to by id.

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "support/rational.hpp"

namespace oasis::model {

using StateIndex = std::uint32_t;
using ActionIndex = std::uint32_t;
using ChoiceIndex = std::uint32_t;  // state * num_actions + action
using EdgeIndex = std::uint32_t;

// P(s' | s, a) for one context. Choice c = s * num_actions + a owns the edges
// [choice_begin[c], choice_begin[c+1]); an empty range means action a is not enabled in s.
// Within a choice, edges are sorted by target and targets are distinct.
struct TransitionMatrix {
  std::uint32_t num_states = 0;
  std::uint32_t num_actions = 0;
  std::vector<EdgeIndex> choice_begin;  // num_states * num_actions + 1 entries
  std::vector<StateIndex> edge_target;
  std::vector<ValueId> edge_probability;

  [[nodiscard]] ChoiceIndex choice(StateIndex s, ActionIndex a) const {
    return s * num_actions + a;
  }
  [[nodiscard]] bool enabled(StateIndex s, ActionIndex a) const {
    const ChoiceIndex c = choice(s, a);
    return choice_begin[c] != choice_begin[c + 1];
  }
  [[nodiscard]] EdgeIndex edges_begin(StateIndex s, ActionIndex a) const {
    return choice_begin[choice(s, a)];
  }
  [[nodiscard]] EdgeIndex edges_end(StateIndex s, ActionIndex a) const {
    return choice_begin[choice(s, a) + 1];
  }
  [[nodiscard]] std::size_t num_edges() const { return edge_target.size(); }
  [[nodiscard]] std::size_t num_enabled_choices() const;
};

// R(s, a) = state[s] + choice[s * num_actions + a]. `choice` is empty when the model has
// only state rewards.
struct RewardTable {
  std::vector<ValueId> state;
  std::vector<ValueId> choice;
};

struct Context {
  std::string name;
  // Shared between contexts that do not override transitions: they cost nothing extra.
  std::shared_ptr<const TransitionMatrix> transitions;
  RewardTable rewards;
};

// The states, named either explicitly or by the valuation of a factored model's variables.
struct StateSpace {
  std::uint32_t size = 0;
  std::vector<std::string> names;        // explicit models: one name per state
  std::vector<std::string> variables;    // factored models: variable names
  std::vector<std::int64_t> valuations;  // factored models: size * variables.size()
  std::vector<StateIndex> initial;

  // "s1" for explicit models, "(x=1,y=0)" for factored ones, "7" for unnamed imports.
  [[nodiscard]] std::string name(StateIndex s) const;
};

// p(phi_t = j | phi_{t-1} = i) as a row-major N x N matrix, and the prior p(phi_0).
// Empty for imported models, which have a single context.
struct SwitchingModel {
  std::vector<Rational> matrix;
  std::vector<Rational> prior;
};

// What the policy maximises: discounted reward or reward over a finite horizon.
struct Objective {
  std::optional<Rational> discount;
  std::optional<std::uint32_t> horizon;
};

struct ExplicitModel {
  std::string name;
  StateSpace states;
  std::vector<std::string> actions;
  RationalPool values;
  std::vector<Context> contexts;
  SwitchingModel switching;
  Objective objective;

  [[nodiscard]] std::uint32_t num_states() const { return states.size; }
  [[nodiscard]] std::uint32_t num_actions() const {
    return static_cast<std::uint32_t>(actions.size());
  }
  // R(s, a) in context `context` as an exact rational.
  [[nodiscard]] Rational reward(std::size_t context, StateIndex s, ActionIndex a) const;
};

// Collects edges in any order and produces a TransitionMatrix: counting-sorts by choice,
// sorts each choice by target and merges repeated targets by adding their probabilities.
class TransitionBuilder {
 public:
  TransitionBuilder(std::uint32_t num_states, std::uint32_t num_actions);

  void reserve(std::size_t edges);
  // For callers that learn the state count only after adding edges (exploration).
  void set_num_states(std::uint32_t num_states);
  void add(StateIndex source, ActionIndex action, StateIndex target, ValueId probability);
  [[nodiscard]] std::size_t size() const { return targets_.size(); }

  // `values` is needed to add probabilities of repeated targets exactly.
  [[nodiscard]] TransitionMatrix finish(RationalPool& values);

 private:
  std::uint32_t num_states_;
  std::uint32_t num_actions_;
  std::vector<ChoiceIndex> choices_;
  std::vector<StateIndex> targets_;
  std::vector<ValueId> probabilities_;
};

// Appends one distribution to the end of `matrix`'s edge arrays: sorts `row` by target
// (stably) and merges repeated targets by adding their probabilities exactly. The caller
// sets choice_begin.
void append_distribution(std::vector<std::pair<StateIndex, ValueId>>& row, RationalPool& values,
                         TransitionMatrix& matrix);

// Structural problems of a model, for tests and for checking imported files: a target out of
// range, a distribution that does not sum to exactly 1, a non-positive probability, arrays of
// the wrong size. Returns the first problem found as a sentence, or nullopt.
std::optional<std::string> find_structural_problem(const ExplicitModel& model);

}  // namespace oasis::model
