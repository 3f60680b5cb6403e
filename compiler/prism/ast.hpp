#pragma once
// The syntax tree of a PRISM program, as written: names unresolved, nothing evaluated.
// checker.cpp resolves and lowers it (expressions: expression_lowering.cpp).

#include <optional>
#include <string>
#include <vector>

#include "support/diagnostics.hpp"

namespace oasis::prism::ast {

struct Expr {
  enum class Kind { Integer, Real, Bool, Name, Unary, Binary, IfThenElse, Call, Extension };
  Kind kind = Kind::Integer;
  // Integer/Real: the literal; Bool: "true"/"false"; Name: the name; Unary/Binary: the
  // operator's spelling; Call: the function's name. Extension: a node of the property
  // language (`P=? [...]`, `"label"`, `filter(...)`), kept by the property parser; `text` is
  // its index there. Programs never contain one.
  std::string text;
  std::vector<Expr> operands;
  SourceRange range;
  // Of the tree: a chain such as 1+1+...+1 is as deep as it is long, and every later pass
  // recurses over it, so the parser bounds it like parenthesis nesting.
  int depth = 1;
};

enum class ConstantType { Int, Double, Bool };

struct Constant {
  std::string name;
  ConstantType type = ConstantType::Int;
  std::optional<Expr> value;  // none: to be given with --const
  SourceRange range;          // the name
};

struct Formula {
  std::string name;
  Expr value;
  SourceRange range;
};

struct Variable {
  std::string name;
  bool boolean = false;
  Expr low, high;  // int only
  std::optional<Expr> init;
  SourceRange range;
};

struct Assignment {
  std::string variable;
  SourceRange variable_range;
  Expr value;
};

struct Update {
  std::optional<Expr> probability;      // none: 1
  std::vector<Assignment> assignments;  // empty: `true`, nothing changes
  SourceRange range;
};

struct Command {
  std::string action;  // empty: unlabelled, `[]`
  SourceRange action_range;
  Expr guard;
  std::vector<Update> updates;
  SourceRange range;
};

struct Rename {
  std::string from, to;
  SourceRange range;
};

struct Module {
  std::string name;
  SourceRange range;
  std::vector<Variable> variables;
  std::vector<Command> commands;
  // `module m2 = m1 [a=b, x=y] endmodule`: a copy of `base` with names replaced.
  std::optional<std::string> base;
  SourceRange base_range;
  std::vector<Rename> renames;
};

struct Label {
  std::string name;
  Expr value;
  SourceRange range;
};

struct RewardItem {
  std::optional<std::string> action;  // none: a state reward; "": `[]`, unlabelled choices
  SourceRange action_range;
  Expr guard;
  Expr value;
  SourceRange range;
};

struct Rewards {
  std::string name;  // may be empty: an unnamed structure
  std::vector<RewardItem> items;
  SourceRange range;
};

enum class ModelType { Dtmc, Mdp };

struct Program {
  ModelType type = ModelType::Mdp;
  bool type_given = false;
  SourceRange type_range;
  std::vector<Constant> constants;
  std::vector<Formula> formulas;
  std::vector<Variable> globals;
  std::vector<Module> modules;
  std::vector<Label> labels;
  std::vector<Rewards> rewards;
  std::optional<Expr> init;  // init ... endinit
  SourceRange init_range;
};

}  // namespace oasis::prism::ast
