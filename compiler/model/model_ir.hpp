#pragma once
// The typed model IR: a checked spec with every name resolved, every constant evaluated and
// every context's behaviour spelled out in full. Explicit models are expressed in the same
// terms as factored ones: one hidden variable holds the state index, `s, a -> p: t` becomes a
// command guarded by "state is s" that sets the state to t. Exploration turns this into an
// ExplicitModel; the geometry layer reads the continuous part.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "model/explicit_model.hpp"
#include "model/expression.hpp"

namespace oasis::model {

enum class ModelKind { Explicit, Factored, Continuous };
enum class MissingPolicy { Error, SelfLoop, Disabled };

struct DiscreteVariable {
  std::string name;
  std::int64_t low = 0;
  std::int64_t high = 0;
  std::int64_t init = 0;
  SourceRange range;
};

struct ContinuousVariable {
  std::string name;
  Rational low;
  Rational high;
  SourceRange range;
};

struct Update {
  std::uint32_t variable = 0;
  Expression value;
  SourceRange range;
};

struct Outcome {
  Expression probability;  // folded to a constant whenever it does not depend on the state
  std::vector<Update> updates;
  SourceRange range;
};

struct Command {
  ActionIndex action = 0;
  Expression guard;
  std::vector<Outcome> outcomes;
  SourceRange range;
};

struct Reward {
  std::optional<ActionIndex> action;
  Expression guard;
  Expression value;
  SourceRange range;
};

// sum_i coefficients[i] * x_i  (<= or <)  bound, over the continuous variables.
struct LinearConstraint {
  std::vector<Rational> coefficients;
  Rational bound;
  bool strict = false;
};

struct Region {
  std::string name;
  std::vector<LinearConstraint> constraints;  // a conjunction: a convex polyhedron
  SourceRange range;
};

struct DisturbanceModel {
  enum class Kind { None, Bounded, Gaussian } kind = Kind::None;
  Rational first;   // lower bound, or mean
  Rational second;  // upper bound, or standard deviation
};

// x' = A x + b + w for one action, over the continuous variables.
struct AffineDynamics {
  std::vector<std::vector<Rational>> matrix;  // n x n
  std::vector<Rational> offset;               // n
  std::vector<DisturbanceModel> disturbance;  // per variable
  SourceRange range;
  // Empty when the map is exactly A x + b. When its coefficients are irrational constants
  // (cos(0.1) * x), A and b are rational roundings of them and approximation[i] bounds
  // |f_i(x) - (A x + b)_i| over the domain: the grid path adds it to its error bound
  // (docs/geometry.md, "Irrational coefficients").
  std::vector<Rational> approximation;
};

// x' = f(x, u) + w for one action, over the continuous variables: `next[i]` is f_i, an
// expression over the continuous variables (Op::ContinuousVariable) and the model's inputs
// (Op::InputVariable), with the functions of docs/spec-language.md. Every continuous model
// has it for every action; `AffineDynamics` is the same map when it is affine and reads no
// input.
struct MapDynamics {
  std::vector<Expression> next;               // n
  std::vector<DisturbanceModel> disturbance;  // per variable
  SourceRange range;
};

// `input u in [lo .. hi] step s;` or `input u in {v1, v2, ...};`: a control input that ranges
// over a finite set of values. The finite actions of a model with inputs are each action with
// each combination of the inputs' values (docs/guarantees.md).
struct InputVariable {
  std::string name;
  std::vector<Rational> values;  // in the order written (ascending for a range)
  SourceRange range;
};

// `objective safety S steps N;` or `objective reach T [while S] [steps N | at N];`: what the
// controller of a continuous model maximises, with sound lower and upper bounds on the true
// system (docs/guarantees.md). S and T are conjunctions of linear constraints over the
// continuous variables; S empty means the whole domain.
struct GuaranteeObjective {
  enum class Kind { Safety, ReachAvoid } kind = Kind::Safety;
  std::vector<LinearConstraint> safe;
  std::vector<LinearConstraint> target;  // reach-avoid only
  std::optional<std::uint64_t> steps;    // bounded; safety always has it
  bool exactly_at_step = false;          // `at N`: in T at step N, in S at every step before
  SourceRange range;
};

// The commands of a context, grouped by action: by_action[a] lists every command of action a.
struct CommandTable {
  std::vector<std::vector<Command>> by_action;
};

struct ContextIR {
  std::string name;
  SourceRange range;
  // A spec that imports a PRISM program: the program's reward structure this context takes
  // (`context c = rewards "name";`, where the range is), or none (`= base`: no rewards).
  std::optional<std::string> reward_structure;
  SourceRange reward_structure_range;
  std::uint32_t command_table = 0;  // contexts that do not override transitions share table 0
  std::vector<Reward> rewards;
  // Per action, continuous models only: the affine form, absent where the action's map is not
  // affine or reads an input, and the map itself, always present.
  std::vector<std::optional<AffineDynamics>> dynamics;
  std::vector<std::optional<MapDynamics>> maps;
};

// `import "robot.nm" { const N = 4; }`: the spec's model is a PRISM program, explored by the
// PRISM front end (which sits above this layer); the spec gives its constants and catalog.
struct ImportedProgram {
  struct Constant {
    std::string name;
    Rational value;
    Type type = Type::Int;  // Bool (value 0 or 1), Int or Real
    SourceRange range;      // the `const` item
  };
  std::string path;  // as written
  SourceRange path_range;
  std::vector<Constant> constants;
};

struct ModelIR {
  std::string name;
  SourceRange range;
  ModelKind kind = ModelKind::Explicit;
  std::vector<std::string> state_names;        // explicit models
  std::vector<DiscreteVariable> variables;     // explicit models: the hidden state variable
  std::vector<ContinuousVariable> continuous;  // continuous models
  std::vector<std::string> actions;
  std::vector<std::vector<std::int64_t>> initial;  // valuations of the initial states
  MissingPolicy missing = MissingPolicy::Error;
  std::vector<CommandTable> command_tables;
  std::vector<Region> regions;
  std::vector<ContextIR> contexts;
  SwitchingModel switching;
  std::vector<PropertySource> properties;  // the catalog's `property` items
  Objective objective;
  SourceRange objective_range;     // the spec's discount or horizon; else the model's name
  std::optional<Rational> period;  // seconds per step (continuous models)
  // Continuous models: the spec's error target per context and cell budget per context, when
  // it gives them (`epsilon e;`, `max_cells n;`).
  std::optional<Rational> epsilon;
  std::optional<std::uint64_t> max_cells;
  // Continuous models: the control inputs, the objective with guarantees, and the uniform grid
  // the objective is solved on (cells per continuous variable, `grid x : 50, y : 50;`).
  std::vector<InputVariable> inputs;
  std::optional<GuaranteeObjective> guarantee;
  std::vector<std::uint64_t> grid_cells;
  SourceRange grid_range;
  // The catalog's `observation` block, checked (discrete models only).
  ObservationSpec observation;
  // Set when the spec imports its model; contexts then name reward structures, and the model's
  // own fields (actions, variables, command tables) are empty.
  std::optional<ImportedProgram> imported;
};

}  // namespace oasis::model
