#pragma once
// The abstract syntax tree of a .oasis spec: what was written, with where it was written.
// Names and numbers are views into the source text, which outlives the tree. Meaning (types,
// name resolution, probabilities) is the checker's job.

#include <memory>
#include <optional>
#include <string_view>
#include <utility>
#include <vector>

#include "frontend/token.hpp"
#include "support/diagnostics.hpp"

namespace oasis::frontend::ast {

struct Name {
  std::string_view text;
  SourceRange range;
};

enum class ExprKind { Number, Boolean, Name, Unary, Binary, Call };

struct Expr {
  ExprKind kind = ExprKind::Number;
  SourceRange range;      // the whole expression
  std::string_view text;  // Number: its spelling; Name and Call: the name; Boolean: true/false
  TokenKind op = TokenKind::Invalid;  // Unary and Binary
  SourceRange op_range;               // where the operator is
  std::vector<std::unique_ptr<Expr>> operands;
  int depth = 1;  // height of the tree; the parser bounds it (kMaxNesting)
};
using ExprPtr = std::unique_ptr<Expr>;

// `x' = e` in a factored update, or a dynamics equation.
struct Assignment {
  Name variable;
  ExprPtr value;
  SourceRange range;
};

// One term `p : target` of a distribution. `probability` is null when the term is written
// without one (a single certain outcome). Explicit models and switching rows have a `target`
// name; factored commands have `updates` (empty for `true`, "nothing changes").
struct Branch {
  ExprPtr probability;
  std::optional<Name> target;
  std::vector<Assignment> updates;
  SourceRange range;
};

struct Distribution {
  std::vector<Branch> branches;
  SourceRange range;
};

// `s, a -> distribution;` in an explicit model.
struct ExplicitTransition {
  Name state;
  Name action;
  Distribution distribution;
  SourceRange range;
};

// `[a] guard -> distribution;` in a factored model.
struct Command {
  Name action;
  ExprPtr guard;
  Distribution distribution;
  SourceRange range;
};

// `reward [a] guard : value;` (the action part is optional).
struct RewardItem {
  std::optional<Name> action;
  ExprPtr guard;
  ExprPtr value;
  SourceRange range;
};

// `disturbance x in [lo, hi];` or `disturbance x ~ gaussian(mean, sd);`
struct Disturbance {
  Name variable;
  bool gaussian = false;
  ExprPtr first;   // lower bound, or mean
  ExprPtr second;  // upper bound, or standard deviation
  SourceRange range;
};

// `dynamics [a] { x' = e; ... disturbance ...; }`
struct Dynamics {
  Name action;
  std::vector<Assignment> equations;
  std::vector<Disturbance> disturbances;
  SourceRange range;
};

// Items a context may override: transitions (explicit or factored), rewards, dynamics.
struct Behaviour {
  std::vector<ExplicitTransition> transitions;
  std::vector<Command> commands;
  std::vector<RewardItem> rewards;
  std::vector<Dynamics> dynamics;
  std::vector<Disturbance> disturbances;  // apply to every action
};

struct ConstDecl {
  Name name;
  ExprPtr value;
  SourceRange range;
};

// `var x : [lo .. hi] init e;` or `continuous x : [lo .. hi];`
struct VarDecl {
  Name name;
  bool continuous = false;
  ExprPtr low;
  ExprPtr high;
  ExprPtr init;  // discrete only; null means the lower bound
  SourceRange range;
};

// `region r = linear constraints;`
struct RegionDecl {
  Name name;
  ExprPtr constraint;
  SourceRange range;
};

enum class MissingTransitions { Error, SelfLoop, Disabled };

struct Setting {  // `discount e;`, `horizon e;`, `period e;`
  ExprPtr value;
  SourceRange range;
};

// `input u in [lo .. hi] step s;` (low, high, step) or `input u in {v1, ...};` (values).
struct InputDecl {
  Name name;
  ExprPtr low;
  ExprPtr high;
  ExprPtr step;
  std::vector<ExprPtr> values;
  SourceRange range;
};

// `objective safety S steps N;` or `objective reach T [while S] [steps N | at N];`
struct ObjectiveDecl {
  bool reach = false;
  ExprPtr target;  // reach only
  ExprPtr safe;    // null: the whole domain
  ExprPtr steps;   // null: unbounded (reach only)
  bool exactly_at_step = false;
  SourceRange range;
};

// `grid x : 50, y : 50;`: cells per continuous variable.
struct GridDecl {
  std::vector<std::pair<Name, ExprPtr>> cells;
  SourceRange range;
};

struct MdpDecl {
  Name name;
  SourceRange range;
  std::vector<Name> states;
  std::vector<Name> actions;
  std::vector<Name> initial;
  std::vector<ConstDecl> constants;
  std::vector<VarDecl> variables;
  std::vector<RegionDecl> regions;
  MissingTransitions missing = MissingTransitions::Error;
  std::optional<SourceRange> missing_range;
  Behaviour behaviour;
  std::optional<Setting> discount;
  std::optional<Setting> horizon;
  std::optional<Setting> period;
  // Continuous models: the abstraction's error target and cell budget (`epsilon e;`,
  // `max_cells n;`), which the command line may override.
  std::optional<Setting> epsilon;
  std::optional<Setting> max_cells;
  // Continuous models with guarantees (docs/guarantees.md).
  std::vector<InputDecl> inputs;
  std::optional<ObjectiveDecl> objective;
  std::optional<GridDecl> grid;
};

struct ContextDecl {
  Name name;
  bool is_base = false;  // `context c = base;`
  // `context c = rewards "time";`: a reward structure of the imported program, its name
  // without the quotes (the range covers them).
  std::optional<Name> reward_structure;
  Behaviour behaviour;
  SourceRange range;
};

// `switching stay p;` or `switching { c1 -> 0.8: c1 + 0.2: c2; ... }`
struct SwitchingDecl {
  ExprPtr stay;
  std::vector<std::pair<Name, Distribution>> rows;
  SourceRange range;
};

// `prior uniform;` or `prior 0.5: c1 + 0.5: c2;`
struct PriorDecl {
  bool uniform = false;
  Distribution distribution;
  SourceRange range;
};

// `object NAME (x, y) { noise a + b * d + c * d * d; detection p; }` in a continuous
// model's observation block.
struct ObjectDecl {
  Name name;
  std::vector<Name> variables;
  ExprPtr noise;      // sigma(d), an expression in the distance `d`
  ExprPtr detection;  // the probability of a detection
  SourceRange range;
};

// `observation { state noise p; reward follows true; }`, or with
// `state confusion { s1 -> 0.8: s1 + 0.2: s2; ... }` for the state model; continuous models
// list `object` items instead.
struct ObservationDecl {
  SourceRange keyword;                   // the word `observation`
  ExprPtr noise;                         // `state noise p;`
  std::optional<SourceRange> confusion;  // `state confusion { ... }`: the whole item
  std::vector<std::pair<Name, Distribution>> rows;
  std::optional<Name> reward_follows;  // `true` or `observed`
  std::vector<ObjectDecl> objects;
  SourceRange range;
};

// `property NAME = P=? [...];`: a PRISM property the catalog states a value for in every
// context (docs/spec-language.md, "Properties"); its text is read by the property parser.
struct PropertyDecl {
  Name name;
  SourceRange text;
};

struct CatalogDecl {
  std::optional<Name> name;
  std::vector<PropertyDecl> properties;
  std::vector<ContextDecl> contexts;
  std::optional<SwitchingDecl> switching;
  std::optional<PriorDecl> prior;
  std::optional<ObservationDecl> observation;
  SourceRange range;
};

// `import "robot.nm" { const N = 4; discount 0.9; }`: a PRISM program in place of an `mdp`
// block. The block is optional.
struct ImportDecl {
  Name path;  // as written, without the quotes
  std::vector<ConstDecl> constants;
  std::optional<Setting> discount;
  std::optional<Setting> horizon;
  SourceRange range;
};

struct SpecFile {
  FileId file = 0;
  std::vector<MdpDecl> mdps;
  std::vector<ImportDecl> imports;
  std::vector<CatalogDecl> catalogs;
};

}  // namespace oasis::frontend::ast
