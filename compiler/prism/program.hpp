#pragma once
// A checked PRISM program: constants evaluated, formulas expanded, renamed modules copied,
// every name resolved to a variable slot or an action, every expression typed and lowered to
// the model IR's expressions (model/expression.hpp), ready to explore.

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "model/expression.hpp"
#include "model/model_ir.hpp"

namespace oasis::prism {

enum class ModelType { Dtmc, Mdp };

// One alternative of a command: with `probability`, set each variable to its value.
struct Update {
  model::Expression probability;
  std::vector<model::Update> assignments;
  SourceRange range;
};

struct Command {
  std::optional<std::uint32_t> action;  // index into Program::actions; none: unlabelled
  model::Expression guard;
  std::vector<Update> updates;
  // The sum of the probabilities when none depends on the state (checked already);
  // otherwise exploration checks it in each state.
  bool constant_probabilities = true;
  std::uint32_t serial = 0;  // its place among all the program's commands
  SourceRange range;
};

struct Module {
  std::string name;
  std::vector<Command> commands;
  std::vector<bool> alphabet;  // per action: whether a command of this module has it
};

struct Label {
  std::string name;
  model::Expression holds;
};

// `[a] guard : value` (action set) or `guard : value` (a state reward).
struct RewardItem {
  enum class Kind { State, Unlabelled, Action } kind = Kind::State;
  std::uint32_t action = 0;  // Kind::Action
  model::Expression guard;
  model::Expression value;
};

struct RewardStructure {
  std::string name;
  std::vector<RewardItem> items;
  SourceRange range;
};

struct Program {
  std::string name;  // the file's stem
  ModelType type = ModelType::Mdp;
  std::vector<model::DiscreteVariable> variables;  // globals, then each module's own
  std::vector<std::string> actions;                // synchronising action labels
  std::vector<Module> modules;
  std::vector<Label> labels;
  std::vector<RewardStructure> rewards;
  // The initial states: one valuation from the variables' `init`s, or every valuation that
  // satisfies `init ... endinit`.
  std::optional<model::Expression> init_predicate;
  SourceRange range;  // the model type, or the start of the file
  // Every name a property may use, sorted, as the program's own expressions read it: each
  // constant that has a value, each formula, each variable (a boolean one reads `x = 1`).
  std::vector<std::pair<std::string, model::Expression>> names;
};

}  // namespace oasis::prism
