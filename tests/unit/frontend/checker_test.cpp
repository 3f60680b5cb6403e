// Unit tests of the spec checker (compiler/frontend/checker.cpp, catalog_checker.cpp,
// expression_checker.cpp).
//
// The first half is a table of `expect_error(source, "substring")` cases, one per diagnostic
// the checker can produce, in the order the diagnostics appear in those three files (the way
// flatbuffers keeps its error tests): when a diagnostic is added, its test goes in the same
// place. The second half checks what a sound spec turns into: exact constant folding, the
// switching matrix and prior, context overrides, continuous dynamics and regions.

#include "frontend/checker.hpp"

#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

#include "frontend/load_spec.hpp"

namespace oasis::frontend {
namespace {

using model::ModelIR;
using model::ModelKind;

// An exact rational in canonical form (mpq_class(2, 4) is not reduced, and only canonical
// rationals compare equal).
Rational q(long numerator, long denominator) {
  Rational value(numerator, denominator);
  value.canonicalize();
  return value;
}

struct Checked {
  std::optional<ModelIR> ir;
  std::string output;
  std::size_t errors = 0;
};

// Runs the whole front end (validation, lexer, parser, checker) on `source`.
Checked check_source(const std::string& source) {
  SourceManager sources;
  std::ostringstream out;
  DiagnosticEngine diagnostics(sources, out, 50);
  const FileId file = sources.add("check.oasis", source);
  Checked result;
  result.ir = check_spec_text(file, diagnostics);
  result.output = out.str();
  result.errors = diagnostics.error_count();
  return result;
}

// The message of a line `check.oasis:LINE:COL: error: MESSAGE`, or nullopt for other lines.
// (Parsed by hand: std::regex trips a false -Wmaybe-uninitialized in the ASan build.)
std::optional<std::string> error_message(std::string_view line) {
  constexpr std::string_view kPrefix = "check.oasis:";
  if (line.substr(0, kPrefix.size()) != kPrefix) return std::nullopt;
  std::size_t i = kPrefix.size();
  for (int number = 0; number < 2; ++number) {
    const std::size_t digits = i;
    while (i < line.size() && line[i] >= '0' && line[i] <= '9')
      ++i;
    if (i == digits || i >= line.size() || line[i] != ':') return std::nullopt;
    ++i;
  }
  constexpr std::string_view kError = " error: ";
  if (line.substr(i, kError.size()) != kError) return std::nullopt;
  return std::string(line.substr(i + kError.size()));
}

// The spec must be refused with an error whose message contains `substring`, reported as
// `check.oasis:LINE:COL: error: ...`.
::testing::AssertionResult expect_error(const std::string& source, const std::string& substring) {
  const Checked checked = check_source(source);
  if (checked.ir) {
    return ::testing::AssertionFailure() << "the spec was accepted; output:\n" << checked.output;
  }
  if (checked.errors == 0) {
    return ::testing::AssertionFailure() << "no model, yet no error was reported";
  }
  std::istringstream lines(checked.output);
  for (std::string line; std::getline(lines, line);) {
    const std::optional<std::string> message = error_message(line);
    if (message && message->find(substring) != std::string::npos) {
      return ::testing::AssertionSuccess();
    }
  }
  return ::testing::AssertionFailure() << "no error contains \"" << substring << "\"; output:\n"
                                       << checked.output;
}

// The spec must be accepted; returns its IR.
ModelIR expect_ok(const std::string& source) {
  Checked checked = check_source(source);
  EXPECT_TRUE(checked.ir) << checked.output;
  EXPECT_EQ(checked.errors, 0U) << checked.output;
  if (!checked.ir) return {};
  return std::move(*checked.ir);
}

// Small sound models that the cases below change one thing in.
const std::string kExplicit = "mdp m { states a, b; actions go; a, go -> b; b, go -> a; }\n";
std::string explicit_model(const std::string& extra) {
  return "mdp m {\n  states a, b;\n  actions go;\n  a, go -> b;\n  b, go -> a;\n" + extra + "\n}\n";
}
std::string factored_model(const std::string& extra) {
  return "mdp m {\n  var x : [0 .. 3];\n  actions go;\n  default self;\n" + extra + "\n}\n";
}
std::string continuous_model(const std::string& extra) {
  return "mdp m {\n  continuous x : [0 .. 1];\n  continuous y : [-1 .. 1];\n  actions go;\n"
         "  default self;\n" +
         extra + "\n}\n";
}
std::string with_catalog(const std::string& model, const std::string& catalog) {
  return model + "catalog {\n" + catalog + "\n}\n";
}

struct ErrorCase {
  std::string name;
  std::string source;
  std::string message;
};

std::ostream& operator<<(std::ostream& out, const ErrorCase& c) {
  return out << c.name;
}

std::vector<ErrorCase> error_cases() {
  std::string many_contexts;
  for (int i = 0; i <= 4096; ++i)
    many_contexts += "context c" + std::to_string(i) + " = base;\n";

  return {
      // ---- checker.cpp ---------------------------------------------------------------------
      {"NoModel", "catalog { context c = base; }",
       "spec declares no model: expected an 'mdp NAME { ... }' block or an 'import \"FILE\";'"},
      {"NoModelInEmptyFile", "", "spec declares no model"},
      {"TwoModels", kExplicit + "mdp n { states c; actions go; c, go -> c; }",
       "a spec holds one 'mdp'; contexts of the same model go in its 'catalog'"},
      {"TwoCatalogs", kExplicit + "catalog { context c = base; } catalog { context d = base; }",
       "a spec holds at most one 'catalog'"},
      {"StatesAndVariables", "mdp m { states a; var x : [0 .. 1]; actions go; a, go -> a; }",
       "a model lists its states or declares variables, not both"},
      {"DiscreteAndContinuous",
       "mdp m { var x : [0 .. 1]; continuous y : [0 .. 1]; actions go; default self; }",
       "mixing discrete ('var') and continuous variables is not supported"},
      {"NoStates", "mdp m { actions go; }",
       "model 'm' has no states: list them with 'states' or declare variables with 'var' or "
       "'continuous'"},
      {"NoActions", "mdp m { states a; }", "model 'm' declares no actions (add 'actions a, b;')"},
      {"DuplicateAction", "mdp m { states a; actions go, go; a, go -> a; }",
       "duplicate action 'go'"},
      // "constant ... needs a value known before exploration" cannot be produced: see
      // ConstantsAreAlwaysKnownBeforeExploration below.
      {"DuplicateConstant", explicit_model("const c = 1; const c = 2;"), "duplicate name 'c'"},
      {"InitInFactoredModel", factored_model("init x;"),
       "'init' lists initial states of explicit models; give variables an 'init' value instead"},
      {"DuplicateState", "mdp m { states a, b, a; actions go; a, go -> b; b, go -> a; }",
       "duplicate name 'a'"},
      {"StateClashesWithConstant", "mdp m { const a = 1; states a, b; actions go; default self; }",
       "duplicate name 'a'"},
      {"UnknownInitialState", explicit_model("init c;"), "unknown state 'c'"},
      {"ConstantAsInitialState", explicit_model("const k = 1; init k;"),
       "constant 'k' is not a state"},
      {"UnknownTransitionTarget",
       "mdp m { states a, b; actions go; a, go -> 1/2: c + 1/2: b; b, go -> a; }",
       "unknown state 'c'"},
      {"UnknownAction", explicit_model("a, stop -> a;"), "unknown action 'stop'"},
      {"UnknownRewardAction", explicit_model("reward [stop] a : 1;"), "unknown action 'stop'"},
      {"EmptyVariableRange", "mdp m { var x : [3 .. 1]; actions go; default self; }",
       "empty range: lower bound 3 is above upper bound 1"},
      {"VariableRangeTooLarge", "mdp m { var x : [0 .. 1099511627776]; actions go; default self; }",
       "range of 'x' is too large (at most 2^40 values)"},
      {"VariableRangeTooLargeNegative",
       "mdp m { var x : [-9223372036854775807 .. 9223372036854775807]; actions go; }",
       "range of 'x' is too large"},
      {"InitialValueOutsideRange", "mdp m { var x : [0 .. 3] init 7; actions go; default self; }",
       "initial value 7 is outside the range [0 .. 3]"},
      {"DuplicateVariable", factored_model("var x : [0 .. 1];"), "duplicate name 'x'"},
      {"EmptyContinuousRange", "mdp m { continuous x : [1 .. 1]; actions go; default self; }",
       "empty range: lower bound 1 is not below upper bound 1"},
      {"DuplicateContinuousVariable", continuous_model("continuous x : [0 .. 2];"),
       "duplicate name 'x'"},
      {"RegionInFactoredModel", factored_model("region r = true;"),
       "regions describe continuous state; this model has no continuous variables"},
      {"RegionWithOr", continuous_model("region r = x < 0.2 | x > 0.8;"),
       "a region must be a conjunction ('&') of linear inequalities over the continuous "
       "variables"},
      {"RegionNotLinear", continuous_model("region r = x * y <= 1;"),
       "a region must be a conjunction ('&') of linear inequalities"},
      {"RegionNegated", continuous_model("region r = !(x < 0.5);"),
       "a region must be a conjunction ('&') of linear inequalities"},
      {"RegionNotEqual", continuous_model("region r = x != 0.5;"),
       "a region must be a conjunction ('&') of linear inequalities"},
      {"RegionFalse", continuous_model("region r = false;"),
       "a region must be a conjunction ('&') of linear inequalities"},
      {"DuplicateRegion", continuous_model("region r = x < 0.5; region r = x > 0.5;"),
       "duplicate name 'r'"},
      {"DiscountAndHorizon", explicit_model("discount 0.9; horizon 10;"),
       "give a 'discount' or a 'horizon', not both"},
      {"DiscountZero", explicit_model("discount 0;"), "discount must be in (0, 1], not 0"},
      {"DiscountAboveOne", explicit_model("discount 1.5;"),
       "discount must be in (0, 1], not 3/2 (1.5)"},
      {"HorizonZero", explicit_model("horizon 0;"), "horizon must be between 1 and 10^9 steps"},
      {"HorizonTooLong", explicit_model("horizon 1000000001;"),
       "horizon must be between 1 and 10^9 steps"},
      {"PeriodNotPositive", continuous_model("period -0.2;"),
       "period must be positive (seconds per step)"},
      {"DisturbanceInDiscreteModel", factored_model("disturbance x in [0 .. 1];"),
       "disturbances belong to models with continuous variables"},
      {"ContextDisturbanceOutsideDynamics",
       with_catalog(continuous_model(""), "context c { disturbance x in [0 .. 1]; }"),
       "a context's disturbance must sit inside its 'dynamics' blocks"},
      {"ExplicitTransitionInFactoredModel", factored_model("a, go -> a;"),
       "'state, action -> ...' transitions belong to models that list their states; use "
       "'[action] guard -> ...'"},
      {"TwoTransitionsForOnePair", explicit_model("a, go -> a;"),
       "state 'a' already has a transition for action 'go'; an MDP gives one distribution per "
       "action"},
      {"NegativeProbability", "mdp m { states a, b; actions go; a, go -> -1/2: a + 3/2: b; }",
       "probability -1/2 (-0.5) is negative"},
      {"ProbabilityAboveOne", "mdp m { states a, b; actions go; a, go -> -1/2: a + 3/2: b; }",
       "probability 3/2 (1.5) is greater than 1"},
      {"ProbabilitiesDoNotSumToOne",
       "mdp m { states a, b; actions go; a, go -> 0.5: a + 0.4: "
       "b; b, go -> a; }",
       "probabilities sum to 9/10 (0.9), not 1"},
      {"FactoredProbabilitiesDoNotSumToOne",
       factored_model("[go] true -> 1/3: (x' = 1) + 1/3: (x' = 2);"),
       "probabilities sum to 2/3 (0.666667), not 1"},
      {"CertainOutcomeBesideAnother", factored_model("[go] true -> (x' = 1) + 1/2: (x' = 2);"),
       "probabilities sum to 3/2 (1.5), not 1"},
      {"CommandInExplicitModel", explicit_model("[go] true -> true;"),
       "'[action] guard -> ...' commands belong to models with 'var' variables"},
      {"UnknownUpdatedVariable", factored_model("[go] true -> (z' = 1);"), "unknown variable 'z'"},
      {"ConstantUpdated", factored_model("const k = 1; [go] true -> (k' = 1);"),
       "constant 'k' cannot be updated"},
      {"VariableUpdatedTwice", factored_model("[go] true -> (x' = 1) & (x' = 0);"),
       "variable 'x' is updated twice in one outcome"},
      {"UpdateNeedsAnInteger", factored_model("[go] true -> (x' = x / 2);"),
       "integer variable 'x' needs an int, not a number (round with floor() or ceil())"},
      {"UpdateWithABoolean", factored_model("[go] true -> (x' = x > 1);"),
       "integer variable 'x' needs an int, not a bool"},
      {"ConstantUpdateOutOfRange", factored_model("[go] true -> (x' = 5);"),
       "value 5 is outside the range [0 .. 3] of 'x'"},
      {"ContinuousRewardWithOr", continuous_model("reward x < 0.2 | x > 0.8 : 1;"),
       "a continuous reward condition must be a conjunction of regions and linear "
       "inequalities"},
      {"DynamicsInFactoredModel", factored_model("dynamics [go] { }"),
       "'dynamics' blocks belong to models with continuous variables"},
      {"DynamicsTwice", continuous_model("dynamics [go] { } dynamics [go] { x' = 0; }"),
       "action 'go' already has dynamics here"},
      {"DynamicsForUnknownAction", continuous_model("dynamics [stop] { }"),
       "unknown action 'stop'"},
      {"EquationForUnknownVariable", continuous_model("dynamics [go] { z' = 1; }"),
       "unknown continuous variable 'z'"},
      {"EquationForAConstant", continuous_model("const k = 1; dynamics [go] { k' = 1; }"),
       "unknown continuous variable 'k'"},
      {"TwoEquationsForOneVariable", continuous_model("dynamics [go] { x' = 1; x' = 2; }"),
       "variable 'x' already has an equation in this block"},
      {"DynamicsNotAffine", continuous_model("dynamics [go] { x' = x * y; }"),
       "the dynamics of action 'go' are not affine (or read an input): a catalog abstracts "
       "affine dynamics only; state an 'objective' to abstract them with guarantees"},
      {"DynamicsDivideByVariable", continuous_model("dynamics [go] { x' = 1 / x; }"),
       "the dynamics of action 'go' are not affine"},
      {"DynamicsWithAFunction", continuous_model("dynamics [go] { x' = abs(x); }"),
       "the dynamics of action 'go' are not affine"},
      {"DynamicsReadingAnInput",
       continuous_model("input u in {0, 1}; dynamics [go] { x' = x + u; }"),
       "the dynamics of action 'go' are not affine (or read an input)"},
      {"ObjectiveWithoutGrid", continuous_model("objective safety x <= 1 steps 3;"),
       "an objective is solved on a grid: add 'grid x : 50, ...;'"},
      {"GridMissingAVariable", continuous_model("objective safety x <= 1 steps 3; grid x : 4;"),
       "the grid gives no cells for 'y' (list every continuous variable)"},
      {"GridTooLarge",
       continuous_model("objective safety x <= 1 steps 3; grid x : 1000000, y : 1000000;"),
       "the grid has more than 10^10 cells"},
      {"GridWithoutObjective", continuous_model("grid x : 4, y : 4;"),
       "'grid' sets the cells of an objective's abstraction; this model states no 'objective'"},
      {"ObjectiveWithACatalog",
       with_catalog(continuous_model("objective reach x >= 1; grid x : 2, y : 2;"),
                    "context c = base;"),
       "a spec states an 'objective' or a 'catalog', not both"},
      {"ObjectiveWithADiscount",
       continuous_model("discount 0.9; objective reach x >= 1; grid x : 2, y : 2;"),
       "this setting is for catalogs"},
      {"ObjectiveOnADiscreteModel", factored_model("objective reach x >= 1; grid x : 2;"),
       "objectives with guarantees belong to models with continuous variables"},
      {"ObjectiveSetNotConvex",
       continuous_model("objective reach x >= 1 | y >= 0; grid x : 2, y : 2;"),
       "an objective's set must be a conjunction ('&') of regions and linear inequalities"},
      {"ObjectiveZeroSteps",
       continuous_model("objective safety x <= 1 steps 0; grid x : 2, y : 2;"),
       "the number of steps must be from 1 to 10^6"},
      {"InputWithoutStep", continuous_model("input u in [0 .. 1] step 0;"),
       "the step must be positive, not 0"},
      {"InputValueTwice", continuous_model("input u in {1, 0.5, 1/2};"),
       "the value 1/2 (0.5) is listed twice"},
      {"InputCombinationsTooMany",
       continuous_model("input u in [0 .. 1] step 1/999; input v in [0 .. 1] step 1/999;"),
       "the inputs combine into more than 100000 values per action: use larger steps"},
      {"InputOnADiscreteModel", factored_model("input u in {0, 1};"),
       "inputs belong to models with continuous variables"},
      {"InputInAReward", continuous_model("input u in {0, 1}; reward x >= u : 1;"),
       "input 'u' cannot be used in a reward condition"},
      {"ExponentNotConstant",
       continuous_model("objective reach x >= 1; grid x : 2, y : 2; dynamics [go] { x' = x ^ y; }"),
       "the exponent must be an integer constant from -64 to 64"},
      {"DivisorReachesZero",
       continuous_model("objective reach x >= 1; grid x : 2, y : 2; dynamics [go] { x' = 1 / y; }"),
       "the divisor can be 0 here"},
      {"LogOfNonPositive",
       continuous_model(
           "objective reach x >= 1; grid x : 2, y : 2; dynamics [go] { y' = log(x); }"),
       "log of a range that reaches 0 or below"},
      {"SineOutsideDynamics", explicit_model("discount sin(1);"),
       "'sin' is allowed only in dynamics"},
      {"DisturbanceOfUnknownVariable",
       continuous_model("dynamics [go] { disturbance z in [0 .. 1]; }"),
       "unknown continuous variable 'z'"},
      {"ModelDisturbanceOfUnknownVariable",
       continuous_model("disturbance z in [0 .. 1]; dynamics [go] { }"),
       "unknown continuous variable 'z'"},
      {"StandardDeviationNotPositive",
       continuous_model("dynamics [go] { disturbance x ~ gaussian(0, 0); }"),
       "standard deviation must be positive"},
      {"EmptyDisturbanceInterval", continuous_model("dynamics [go] { disturbance x in [1 .. 0]; }"),
       "empty disturbance interval: 1 is above 0"},
      {"MissingTransition", "mdp m { states a, b; actions go; a, go -> b; }",
       "state 'b' has no transition for action 'go' (add one, or write 'default self;' or "
       "'default disabled;' in the model)"},
      {"MissingDynamics", "mdp m { continuous x : [0 .. 1]; actions go, stop; dynamics [go] { } }",
       "action 'stop' has no 'dynamics' block (add one, or write 'default self;' for x' = x)"},
      {"EmptyCatalog", with_catalog(kExplicit, "switching stay 1;"),
       "catalog is empty: declare at least one 'context'"},
      {"TooManyContexts", with_catalog(kExplicit, many_contexts),
       "catalog has more than 4096 contexts (the switching model alone would need N^2 "
       "entries)"},
      {"DuplicateContext",
       with_catalog(kExplicit, "context c = base; context c { reward a : 1; } switching stay 1;"),
       "duplicate context 'c'"},
      {"EmptyContext", with_catalog(kExplicit, "context c { }"),
       "context 'c' is empty, so it names nothing to change; to use the base model as it is, "
       "write 'context c = base;'"},

      // ---- catalog_checker.cpp -------------------------------------------------------------
      {"UnknownContextInPrior", with_catalog(kExplicit, "context c = base; prior 1: zz;"),
       "unknown context 'zz'"},
      {"UnknownContextInSwitchingRow",
       with_catalog(kExplicit, "context c = base; switching { c -> 1: zz; }"),
       "unknown context 'zz'"},
      {"SwitchingProbabilityAboveOne",
       with_catalog(kExplicit,
                    "context c = base; context d = base;"
                    "switching { c -> 1.5: c + -0.5: d; d -> d; }"),
       "probability 3/2 (1.5) is greater than 1"},
      {"NegativePriorProbability",
       with_catalog(kExplicit,
                    "context c = base; context d = base; switching stay 0.5;"
                    "prior 1.5: c + -0.5: d;"),
       "probability -1/2 (-0.5) is negative"},
      {"SwitchingRowDoesNotSumToOne",
       with_catalog(kExplicit,
                    "context c = base; context d = base;"
                    "switching { c -> 0.5: c + 0.4: d; d -> d; }"),
       "probabilities sum to 9/10 (0.9), not 1"},
      {"PriorDoesNotSumToOne",
       with_catalog(kExplicit,
                    "context c = base; context d = base; switching stay 0.5;"
                    "prior 1/3: c + 1/3: d;"),
       "probabilities sum to 2/3 (0.666667), not 1"},
      {"StayAboveOne",
       with_catalog(kExplicit, "context c = base; context d = base; switching stay 1.2;"),
       "probability of staying must be in [0, 1], not 6/5 (1.2)"},
      {"StayNegative",
       with_catalog(kExplicit, "context c = base; context d = base; switching stay -1;"),
       "probability of staying must be in [0, 1], not -1"},
      {"StayBelowOneWithOneContext",
       with_catalog(kExplicit, "context c = base; switching stay 0.5;"),
       "with a single context the probability of staying is 1"},
      {"UnknownContextRow",
       with_catalog(kExplicit, "context c = base; switching { c -> c; zz -> c; }"),
       "unknown context 'zz'"},
      {"TwoRowsForOneContext",
       with_catalog(kExplicit,
                    "context c = base; context d = base;"
                    "switching { c -> c; c -> d; d -> d; }"),
       "context 'c' already has a row"},
      {"MissingSwitchingRow",
       with_catalog(kExplicit, "context c = base; context d = base; switching { c -> c; }"),
       "switching model has no row for context 'd'"},
      {"NoSwitchingModel", with_catalog(kExplicit, "context c = base; context d = base;"),
       "catalog has 2 contexts but no switching model (add e.g. 'switching stay 0.8;')"},

      // ---- expression_checker.cpp ----------------------------------------------------------
      {"NumberOutOfRange", explicit_model("discount 1e100001;"),
       "number '1e100001' is out of range"},
      {"UnknownName", factored_model("[go] y > 0 -> true;"), "unknown name 'y'"},
      {"UnknownNameInConstant", factored_model("const c = x + 1;"), "unknown name 'x'"},
      {"VariableInConstantExpression", factored_model("var y : [0 .. x];"),
       "variable 'x' cannot be used in a constant expression"},
      {"StateInConstantExpression", explicit_model("discount a;"),
       "state 'a' cannot be used in a constant expression"},
      {"ContinuousVariableInRewardValue", continuous_model("reward true : x;"),
       "continuous variable 'x' cannot be used in a reward value"},
      {"RegionInDynamics", continuous_model("region r = x < 1; dynamics [go] { x' = r; }"),
       "region 'r' cannot be used in dynamics"},
      {"RegionInRewardValue", continuous_model("region r = x < 1; reward r : r;"),
       "region 'r' cannot be used in a reward value"},
      {"StateInExplicitProbability",
       "mdp m { states a, b; actions go; a, go -> a: b + 0: a; b, go -> a; }",
       "state 'a' cannot be used in a probability"},
      {"GuardNeedsABool", factored_model("[go] x -> true;"), "a guard needs a bool, not an int"},
      {"NotNeedsABool", factored_model("[go] !x -> true;"), "'!' needs a bool, not an int"},
      {"MinusNeedsANumber", factored_model("[go] -true == 1 -> true;"),
       "'-' needs a number, not a bool"},
      {"AndNeedsBools", factored_model("[go] x & true -> true;"), "'&' needs a bool, not an int"},
      {"OrNeedsBools", factored_model("[go] true | 1 -> true;"), "'|' needs a bool, not an int"},
      {"EqualityOfBoolAndNumber", factored_model("[go] true == 1 -> true;"),
       "'==' needs a bool, not an int"},
      {"OrderingOfBools", factored_model("[go] true < false -> true;"),
       "'<' needs a number, not a bool"},
      {"ArithmeticOnBools", factored_model("[go] true + 1 > 0 -> true;"),
       "'+' needs a number, not a bool"},
      {"FunctionOfABool", factored_model("[go] abs(true) > 0 -> true;"),
       "'abs' needs a number, not a bool"},
      {"RewardValueNeedsANumber", explicit_model("reward a : true;"),
       "a reward value needs a number, not a bool"},
      {"RewardConditionNeedsABool", explicit_model("reward 1 : 1;"),
       "a reward condition needs a bool, not an int"},
      {"ProbabilityNeedsANumber", factored_model("[go] true -> true: (x' = 1);"),
       "a probability needs a number, not a bool"},
      {"RegionNeedsABool", continuous_model("region r = x;"),
       "a region needs a bool, not a number"},
      {"EquationNeedsANumber", continuous_model("dynamics [go] { x' = true; }"),
       "an equation needs a number, not a bool"},
      {"BoundNeedsANumber", "mdp m { var x : [false .. 3]; actions go; default self; }",
       "a lower bound needs a number, not a bool"},
      {"UnknownFunction", explicit_model("discount cbrt(2);"),
       "unknown function 'cbrt' (functions are min, max, floor, ceil, abs, mod, pow; in dynamics "
       "also sin, cos, tan, atan, exp, log, sqrt)"},
      {"TooFewArguments", explicit_model("discount min();"), "wrong number of arguments to 'min'"},
      {"TooManyArgumentsToFloor", explicit_model("discount floor(1, 2);"),
       "wrong number of arguments to 'floor'"},
      {"ModNeedsOneMore", explicit_model("discount mod(1);"), "wrong number of arguments to 'mod'"},
      {"ModNeedsIntegers", explicit_model("discount mod(1.5, 2);"),
       "'mod' needs integer arguments"},
      {"DivisionByZero", explicit_model("discount 1 / (2 - 2);"), "division by zero"},
      {"ModByZero", explicit_model("discount mod(1, 0);"), "mod by zero"},
      {"AdditionOverflow", explicit_model("discount 9223372036854775807 + 1;"),
       "integer overflow (values must fit in 64 bits)"},
      {"MultiplicationOverflow", explicit_model("discount 4294967296 * 4294967296;"),
       "integer overflow"},
      {"NegationOverflow", explicit_model("discount -(-9223372036854775807 - 1);"),
       "integer overflow"},
      {"AbsOverflow", explicit_model("discount abs(-9223372036854775807 - 1);"),
       "integer overflow"},
      {"FloorOverflow", explicit_model("discount floor(1e30);"), "integer overflow"},
      {"LiteralTooLargeForArithmetic", explicit_model("discount 99999999999999999999 - 1;"),
       "integer overflow"},
      {"BoundNotAnInteger", "mdp m { var x : [0 .. 1/2]; actions go; default self; }",
       "an upper bound must be an integer that fits in 64 bits, not 1/2 (0.5)"},
      {"BoundTooLarge", "mdp m { var x : [0 .. 99999999999999999999]; actions go; }",
       "an upper bound must be an integer that fits in 64 bits, not 99999999999999999999"},
      {"HorizonNotAnInteger", explicit_model("horizon 2.5;"),
       "the horizon must be an integer that fits in 64 bits, not 5/2 (2.5)"},
      {"InitialValueNotAnInteger", "mdp m { var x : [0 .. 3] init 0.5; actions go; }",
       "an initial value must be an integer that fits in 64 bits"},
  };
}

class CheckerError : public ::testing::TestWithParam<ErrorCase> {};

TEST_P(CheckerError, IsReported) {
  EXPECT_TRUE(expect_error(GetParam().source, GetParam().message)) << GetParam().source;
}

INSTANTIATE_TEST_SUITE_P(Table, CheckerError, ::testing::ValuesIn(error_cases()),
                         [](const ::testing::TestParamInfo<ErrorCase>& param_info) {
                           return param_info.param.name;
                         });

// Constants are declared before states, variables and regions, and a constant may only use
// earlier constants, so every constant folds: "needs a value known before exploration" is a
// defensive check. The nearest specs get the error that explains them.
TEST(CheckerErrorUnreachable, ConstantsAreAlwaysKnownBeforeExploration) {
  EXPECT_TRUE(expect_error(factored_model("const c = x;"), "unknown name 'x'"));
  EXPECT_TRUE(expect_error(explicit_model("const c = a;"), "unknown name 'a'"));
  EXPECT_TRUE(expect_error(continuous_model("const c = x;"), "unknown name 'x'"));
  EXPECT_TRUE(expect_error(factored_model("const c = d; const d = 1;"), "unknown name 'd'"));
}

TEST(CheckerErrors, DisturbanceInADiscreteModelIsRefused) {
  // A disturbance only means something for continuous state; in a discrete model it would be
  // ignored without a word, whatever it names.
  EXPECT_TRUE(expect_error(factored_model("disturbance x in [0 .. 1];"),
                           "disturbances belong to models with continuous variables"));
  EXPECT_TRUE(expect_error(explicit_model("disturbance nothing ~ gaussian(0, 1);"),
                           "disturbances belong to models with continuous variables"));
  EXPECT_TRUE(expect_error(with_catalog(kExplicit, "context c { disturbance x in [0 .. 1]; }"),
                           "disturbances belong to models with continuous variables"));
}

TEST(CheckerErrors, ModelDisturbanceIsCheckedOnceWhateverTheDynamics) {
  // A bad model-level disturbance is one mistake: one error, not one per dynamics block...
  const Checked twice = check_source(
      "mdp m { continuous x : [0 .. 1]; actions go, stop; disturbance z in [0 .. 1];\n"
      "  dynamics [go] { } dynamics [stop] { } }");
  EXPECT_FALSE(twice.ir);
  EXPECT_EQ(twice.errors, 1U) << twice.output;
  // ...and it is reported even when no action has a dynamics block.
  EXPECT_TRUE(expect_error(continuous_model("disturbance z in [0 .. 1];"),
                           "unknown continuous variable 'z'"));
  EXPECT_TRUE(expect_error(continuous_model("disturbance x in [1 .. 0];"),
                           "empty disturbance interval: 1 is above 0"));
}

TEST(CheckerErrors, DiagnosticsPointAtTheProblem) {
  const Checked checked = check_source(
      "mdp m {\n"
      "  states a, b;\n"
      "  actions go;\n"
      "  a, go -> 0.5: a + 0.4: b;\n"
      "  b, go -> a;\n"
      "}\n");
  EXPECT_EQ(checked.output,
            "check.oasis:4:12: error: probabilities sum to 9/10 (0.9), not 1\n"
            "  a, go -> 0.5: a + 0.4: b;\n"
            "           ^~~~~~~~~~~~~~~\n");
}

TEST(CheckerErrors, DuplicateNamesHaveANoteAtTheFirst) {
  const Checked checked = check_source("mdp m { states a, b, a; actions go; default self; }");
  EXPECT_NE(checked.output.find("check.oasis:1:22: error: duplicate name 'a'"), std::string::npos)
      << checked.output;
  EXPECT_NE(checked.output.find("check.oasis:1:16: note: 'a' was first declared here"),
            std::string::npos)
      << checked.output;
}

TEST(CheckerErrors, EveryRepeatHasANoteAtTheFirst) {
  struct NoteCase {
    std::string source;
    std::string note;  // `check.oasis:LINE:COL: note: ...`
  };
  const std::vector<NoteCase> cases = {
      {"mdp m {\n  states a, b;\n  actions go;\n  a, go -> b;\n  b, go -> a;\n  a, go -> a;\n}",
       "check.oasis:4:3: note: the first transition is here"},
      {factored_model("[go] true -> (x' = 1) & (x' = 2);"),
       "check.oasis:5:15: note: first update here"},
      {continuous_model("dynamics [go] { }\n  dynamics [go] { }"),
       "check.oasis:6:1: note: first dynamics here"},
      {with_catalog(kExplicit,
                    "context c = base; context d = base;\n"
                    "switching { c -> c; d -> d; c -> d; }"),
       "check.oasis:4:13: note: first row here"},
      {with_catalog(kExplicit, "context c = base; context c = base;"),
       "check.oasis:3:9: note: 'c' was first declared here"},
      {"mdp m { states a; actions go, go; default self; }",
       "check.oasis:1:27: note: 'go' was first declared here"},
  };
  for (const NoteCase& c : cases) {
    const Checked checked = check_source(c.source);
    EXPECT_FALSE(checked.ir);
    EXPECT_NE(checked.output.find(c.note), std::string::npos) << c.note << "\n" << checked.output;
  }
}

TEST(CheckerErrors, SeveralErrorsInOneSpecAreAllReported) {
  const Checked checked =
      check_source(factored_model("[go] x == 0 -> (x' = 9);\n"
                                  "[go] x == 1 -> (z' = 1);\n"
                                  "reward true : y;\n"));
  EXPECT_FALSE(checked.ir);
  EXPECT_EQ(checked.errors, 3U) << checked.output;
}

// ---- what sound specs turn into -------------------------------------------------------------

TEST(Checker, ConstantFoldingIsExact) {
  const ModelIR ir = expect_ok(factored_model(
      "const third = 1/3;\n"
      "const half = third + 1/6;\n"
      "discount half;\n"
      "[go] 1/3 + 1/6 == 1/2 & 0.1 + 0.2 == 0.3 -> half: (x' = 1) + 1/2: (x' = 2);\n"));
  ASSERT_TRUE(ir.objective.discount);
  EXPECT_EQ(*ir.objective.discount, Rational(1, 2));
  ASSERT_EQ(ir.command_tables.size(), 1U);
  const model::Command& command = ir.command_tables[0].by_action[0].at(0);
  // The guard folded to the constant `true`.
  ASSERT_TRUE(command.guard.is_constant());
  EXPECT_EQ(command.guard.type, model::Type::Bool);
  EXPECT_EQ(command.guard.constant, 1);
  ASSERT_EQ(command.outcomes.size(), 2U);
  ASSERT_TRUE(command.outcomes[0].probability.is_constant());
  EXPECT_EQ(command.outcomes[0].probability.constant, Rational(1, 2));
}

TEST(Checker, FoldingOfFunctionsAndIntegers) {
  const ModelIR ir =
      expect_ok(factored_model("const a = min(3, 1, 2) + max(1, 5) * 2;\n"       // 1 + 10
                               "const b = floor(-7/2) + ceil(7/2) + abs(-4);\n"  // -4 + 4 + 4
                               "const c = mod(-7, 3) + mod(7, -3);\n"            // 2 + -2
                               "[go] x == a - 11 + b - 4 + c -> (x' = a - 8);\n"));
  const model::Command& command = ir.command_tables[0].by_action[0].at(0);
  // x == 0 stays a comparison with the variable; the update folded to the constant 3.
  EXPECT_FALSE(command.guard.is_constant());
  EXPECT_EQ(command.guard.operands.at(1).constant, 0);
  const model::Update& update = command.outcomes.at(0).updates.at(0);
  ASSERT_TRUE(update.value.is_constant());
  EXPECT_EQ(update.value.constant, 3);
  EXPECT_EQ(update.value.type, model::Type::Int);
}

TEST(Checker, ModFollowsTheSignOfTheDivisorEvenAtTheLimits) {
  // Each variable's range is the single value under test.
  const std::vector<std::pair<std::string, std::int64_t>> cases = {
      {"mod(-7, 3)", 2},     {"mod(7, -3)", -2},
      {"mod(-7, -3)", -1},   {"mod(7, 3)", 1},
      {"mod(MIN, -1)", 0},   {"mod(1, MIN)", INT64_MIN + 1},
      {"mod(-1, MIN)", -1},  {"mod(MIN, MIN)", 0},
      {"mod(MAX, MIN)", -1}, {"mod(MIN, MAX)", INT64_MAX - 1},
      {"mod(MAX, 2)", 1},    {"mod(MIN, 3)", 1},
  };
  std::string spec =
      "mdp m {\n  const MAX = 9223372036854775807;\n  const MIN = -MAX - 1;\n"
      "  actions go;\n  default self;\n";
  for (std::size_t i = 0; i < cases.size(); ++i) {
    spec +=
        "  var v" + std::to_string(i) + " : [" + cases[i].first + " .. " + cases[i].first + "];\n";
  }
  const ModelIR ir = expect_ok(spec + "}\n");
  ASSERT_EQ(ir.variables.size(), cases.size());
  for (std::size_t i = 0; i < cases.size(); ++i) {
    EXPECT_EQ(ir.variables[i].low, cases[i].second) << cases[i].first;
  }
}

TEST(Checker, StateDependentProbabilitiesStayExpressions) {
  const ModelIR ir =
      expect_ok(factored_model("[go] true -> x / 3 : (x' = 0) + (3 - x) / 3 : (x' = 3);"));
  const model::Command& command = ir.command_tables[0].by_action[0].at(0);
  EXPECT_FALSE(command.outcomes[0].probability.is_constant());
  EXPECT_TRUE(command.outcomes[0].probability.depends_on_state());
  EXPECT_EQ(command.outcomes[0].probability.type, model::Type::Real);
}

TEST(Checker, ExplicitModelIr) {
  const ModelIR ir = expect_ok(
      "mdp robot {\n"
      "  states s1, s2, s3;\n"
      "  actions L, R;\n"
      "  init s3;\n"
      "  default disabled;\n"
      "  s1, L -> 1/4: s1 + 3/4: s2;\n"
      "  s2, R -> s3;\n"
      "  horizon 12;\n"
      "}\n");
  EXPECT_EQ(ir.name, "robot");
  EXPECT_EQ(ir.kind, ModelKind::Explicit);
  EXPECT_EQ(ir.state_names, (std::vector<std::string>{"s1", "s2", "s3"}));
  EXPECT_EQ(ir.actions, (std::vector<std::string>{"L", "R"}));
  ASSERT_EQ(ir.variables.size(), 1U);  // the hidden state index
  EXPECT_EQ(ir.variables[0].low, 0);
  EXPECT_EQ(ir.variables[0].high, 2);
  EXPECT_EQ(ir.initial, (std::vector<std::vector<std::int64_t>>{{2}}));
  EXPECT_EQ(ir.missing, model::MissingPolicy::Disabled);
  EXPECT_EQ(ir.objective.horizon, 12U);
  EXPECT_FALSE(ir.objective.discount);

  ASSERT_EQ(ir.command_tables.size(), 1U);
  const auto& by_action = ir.command_tables[0].by_action;
  ASSERT_EQ(by_action.size(), 2U);
  ASSERT_EQ(by_action[0].size(), 1U);
  const model::Command& command = by_action[0][0];
  EXPECT_EQ(command.action, 0U);
  EXPECT_EQ(command.guard.op, model::Op::StateIs);
  EXPECT_EQ(command.guard.slot, 0U);
  ASSERT_EQ(command.outcomes.size(), 2U);
  EXPECT_EQ(command.outcomes[0].probability.constant, Rational(1, 4));
  EXPECT_EQ(command.outcomes[0].updates.at(0).value.constant, 0);
  EXPECT_EQ(command.outcomes[1].probability.constant, Rational(3, 4));
  EXPECT_EQ(command.outcomes[1].updates.at(0).value.constant, 1);
  ASSERT_EQ(by_action[1].size(), 1U);
  EXPECT_EQ(by_action[1][0].guard.slot, 1U);
  EXPECT_EQ(by_action[1][0].outcomes.at(0).probability.constant, 1);

  // Without a catalog: one context named "default", staying put with certainty.
  ASSERT_EQ(ir.contexts.size(), 1U);
  EXPECT_EQ(ir.contexts[0].name, "default");
  EXPECT_EQ(ir.contexts[0].command_table, 0U);
  EXPECT_EQ(ir.switching.matrix, std::vector<Rational>{Rational(1)});
  EXPECT_EQ(ir.switching.prior, std::vector<Rational>{Rational(1)});
}

TEST(Checker, ExplicitInitialStateDefaultsToTheFirst) {
  const ModelIR ir = expect_ok(kExplicit);
  EXPECT_EQ(ir.initial, (std::vector<std::vector<std::int64_t>>{{0}}));
  EXPECT_EQ(ir.missing, model::MissingPolicy::Error);
}

TEST(Checker, FactoredModelIr) {
  const ModelIR ir = expect_ok(
      "mdp m {\n"
      "  const N = 4;\n"
      "  var x : [0 .. N - 1];\n"
      "  var y : [-2 .. 2] init -1;\n"
      "  actions go;\n"
      "  default self;\n"
      "  period 1/5;\n"
      "}\n");
  EXPECT_EQ(ir.kind, ModelKind::Factored);
  ASSERT_EQ(ir.variables.size(), 2U);
  EXPECT_EQ(ir.variables[0].name, "x");
  EXPECT_EQ(ir.variables[0].low, 0);
  EXPECT_EQ(ir.variables[0].high, 3);
  EXPECT_EQ(ir.variables[0].init, 0);  // no init: the lower bound
  EXPECT_EQ(ir.variables[1].low, -2);
  EXPECT_EQ(ir.variables[1].init, -1);
  EXPECT_EQ(ir.initial, (std::vector<std::vector<std::int64_t>>{{0, -1}}));
  EXPECT_EQ(ir.missing, model::MissingPolicy::SelfLoop);
  ASSERT_TRUE(ir.period);
  EXPECT_EQ(*ir.period, Rational(1, 5));
}

TEST(Checker, SwitchingStayWithThreeContexts) {
  const ModelIR ir = expect_ok(with_catalog(
      kExplicit, "context c1 = base; context c2 = base; context c3 = base; switching stay 0.8;"));
  ASSERT_EQ(ir.contexts.size(), 3U);
  const Rational stay(4, 5);
  const Rational move(1, 10);
  ASSERT_EQ(ir.switching.matrix.size(), 9U);
  for (std::size_t i = 0; i < 3; ++i) {
    Rational row_sum = 0;
    for (std::size_t j = 0; j < 3; ++j) {
      EXPECT_EQ(ir.switching.matrix[i * 3 + j], i == j ? stay : move) << i << "," << j;
      row_sum += ir.switching.matrix[i * 3 + j];
    }
    EXPECT_EQ(row_sum, 1);
  }
  // No prior given: uniform.
  EXPECT_EQ(ir.switching.prior, std::vector<Rational>(3, Rational(1, 3)));
}

TEST(Checker, PriorUniformAndExplicit) {
  const ModelIR uniform =
      expect_ok(with_catalog(kExplicit,
                             "context c1 = base; context c2 = base; context c3 = base;"
                             "switching stay 1; prior uniform;"));
  EXPECT_EQ(uniform.switching.prior, std::vector<Rational>(3, Rational(1, 3)));
  EXPECT_EQ(uniform.switching.matrix, (std::vector<Rational>{1, 0, 0, 0, 1, 0, 0, 0, 1}));

  const ModelIR given = expect_ok(
      with_catalog(kExplicit,
                   "context c1 = base; context c2 = base; context c3 = base;"
                   "switching stay 0; prior 0.5: c3 + 0.25: c1 + 0.125: c1 + 0.125: c2;"));
  EXPECT_EQ(given.switching.prior,
            (std::vector<Rational>{Rational(3, 8), Rational(1, 8), Rational(1, 2)}));
  // stay 0: move to each of the two others with probability 1/2.
  EXPECT_EQ(given.switching.matrix[0], 0);
  EXPECT_EQ(given.switching.matrix[1], Rational(1, 2));
}

TEST(Checker, SwitchingMatrixRows) {
  const ModelIR ir =
      expect_ok(with_catalog(kExplicit,
                             "context a = base; context b = base;\n"
                             "switching { b -> 0.3: a + 0.7: b; a -> 0.8: a + 0.2: b; }\n"
                             "prior 1: b;"));
  EXPECT_EQ(ir.switching.matrix, (std::vector<Rational>{Rational(4, 5), Rational(1, 5),
                                                        Rational(3, 10), Rational(7, 10)}));
  EXPECT_EQ(ir.switching.prior, (std::vector<Rational>{0, 1}));
  EXPECT_EQ(ir.contexts[0].name, "a");
  EXPECT_EQ(ir.contexts[1].name, "b");
}

// Finds the explicit transition of `state` under `action` in a command table and returns
// it as (target, probability) pairs.
std::vector<std::pair<std::int64_t, Rational>> explicit_row(const ModelIR& ir, std::uint32_t table,
                                                            std::uint32_t action,
                                                            std::uint32_t state) {
  std::vector<std::pair<std::int64_t, Rational>> row;
  int found = 0;
  for (const model::Command& command : ir.command_tables.at(table).by_action.at(action)) {
    if (command.guard.slot != state) continue;
    ++found;
    for (const model::Outcome& outcome : command.outcomes) {
      row.emplace_back(outcome.updates.at(0).value.constant.get_num().get_si(),
                       outcome.probability.constant);
    }
  }
  EXPECT_LE(found, 1) << "two commands for one (state, action)";
  return row;
}

TEST(Checker, ExplicitContextReplacesOnlyItsStateActionPair) {
  const ModelIR ir =
      expect_ok(with_catalog("mdp m {\n"
                             "  states a, b;\n"
                             "  actions go, stay;\n"
                             "  a, go -> b;      b, go -> a;\n"
                             "  a, stay -> a;    b, stay -> b;\n"
                             "  reward a : 1;\n"
                             "}\n",
                             "context plain = base;\n"
                             "context slippery { a, go -> 1/2: a + 1/2: b; }\n"
                             "switching stay 0.9;"));
  ASSERT_EQ(ir.contexts.size(), 2U);
  EXPECT_EQ(ir.contexts[0].command_table, 0U);  // the base table
  ASSERT_EQ(ir.command_tables.size(), 2U);
  const std::uint32_t slippery = ir.contexts[1].command_table;
  EXPECT_EQ(slippery, 1U);
  using Row = std::vector<std::pair<std::int64_t, Rational>>;
  // The overridden pair...
  EXPECT_EQ(explicit_row(ir, slippery, 0, 0), (Row{{0, Rational(1, 2)}, {1, Rational(1, 2)}}));
  // ...and every other pair as in the base.
  EXPECT_EQ(explicit_row(ir, slippery, 0, 1), (Row{{0, 1}}));
  EXPECT_EQ(explicit_row(ir, slippery, 1, 0), (Row{{0, 1}}));
  EXPECT_EQ(explicit_row(ir, slippery, 1, 1), (Row{{1, 1}}));
  // The base table is untouched.
  EXPECT_EQ(explicit_row(ir, 0, 0, 0), (Row{{1, 1}}));
  // Neither context gives rewards: both keep the base's.
  EXPECT_EQ(ir.contexts[0].rewards.size(), 1U);
  EXPECT_EQ(ir.contexts[1].rewards.size(), 1U);
}

TEST(Checker, FactoredContextReplacesAllCommandsOfItsAction) {
  const ModelIR ir =
      expect_ok(with_catalog("mdp m {\n"
                             "  var x : [0 .. 3];\n"
                             "  actions up, down;\n"
                             "  default self;\n"
                             "  [up] x < 2 -> (x' = x + 1);\n"
                             "  [up] x >= 2 -> (x' = 3);\n"
                             "  [down] x > 0 -> (x' = x - 1);\n"
                             "}\n",
                             "context sticky { [up] x == 0 -> 1/2: (x' = 1) + 1/2: true; }\n"
                             "context same = base;\n"
                             "switching stay 1;"));
  ASSERT_EQ(ir.command_tables.size(), 2U);
  EXPECT_EQ(ir.command_tables[0].by_action[0].size(), 2U);
  const std::uint32_t sticky = ir.contexts[0].command_table;
  EXPECT_EQ(sticky, 1U);
  EXPECT_EQ(ir.contexts[1].command_table, 0U);
  const auto& up = ir.command_tables[sticky].by_action[0];
  ASSERT_EQ(up.size(), 1U);  // both base commands of `up` are gone
  EXPECT_EQ(up[0].outcomes.size(), 2U);
  // `down` is as in the base.
  ASSERT_EQ(ir.command_tables[sticky].by_action[1].size(), 1U);
  EXPECT_EQ(ir.command_tables[sticky].by_action[1][0].range.begin.offset,
            ir.command_tables[0].by_action[1][0].range.begin.offset);
}

TEST(Checker, ContextRewardsReplaceAllBaseRewards) {
  const ModelIR ir = expect_ok(
      with_catalog(explicit_model("reward a : 1;\n  reward [go] b : 2;\n  reward true : 3;"),
                   "context quiet { reward b : 5; }\n"
                   "context loud = base;\n"
                   "context moved { a, go -> a; }\n"
                   "switching stay 0.5;"));
  ASSERT_EQ(ir.contexts.size(), 3U);
  ASSERT_EQ(ir.contexts[0].rewards.size(), 1U);  // replaced, not added to
  EXPECT_FALSE(ir.contexts[0].rewards[0].action);
  EXPECT_EQ(ir.contexts[0].rewards[0].value.constant, 5);
  EXPECT_EQ(ir.contexts[1].rewards.size(), 3U);  // `= base`: all of the model's
  ASSERT_EQ(ir.contexts[2].rewards.size(), 3U);  // transitions only: rewards as in the base
  ASSERT_TRUE(ir.contexts[2].rewards[1].action);
  EXPECT_EQ(*ir.contexts[2].rewards[1].action, 0U);
  EXPECT_EQ(ir.contexts[2].rewards[1].value.constant, 2);
  // A context that only changes rewards shares the base's transitions.
  EXPECT_EQ(ir.contexts[0].command_table, 0U);
  EXPECT_NE(ir.contexts[2].command_table, 0U);
}

TEST(Checker, ContinuousDynamicsAreAffineMatrices) {
  const ModelIR ir = expect_ok(
      "mdp m {\n"
      "  continuous x : [0 .. 5];\n"
      "  continuous y : [-3 .. 3];\n"
      "  actions turn, stop, drift;\n"
      "  const c = 0.5;\n"
      "  disturbance x in [-0.3 .. 0.3];\n"
      "  dynamics [turn] {\n"
      "    x' = 2 * x + 3 * y - 1;\n"
      "    y' = -(x - y) / 4 + c;\n"
      "    disturbance y ~ gaussian(0, 0.05);\n"
      "  }\n"
      "  dynamics [stop] { }\n"
      "  dynamics [drift] { y' = x; }\n"
      "  period 0.2;\n"
      "}\n");
  EXPECT_EQ(ir.kind, ModelKind::Continuous);
  ASSERT_EQ(ir.continuous.size(), 2U);
  EXPECT_EQ(ir.continuous[0].name, "x");
  EXPECT_EQ(ir.continuous[1].low, -3);
  EXPECT_EQ(ir.continuous[1].high, 3);
  ASSERT_EQ(ir.contexts.size(), 1U);
  const auto& dynamics = ir.contexts[0].dynamics;
  ASSERT_EQ(dynamics.size(), 3U);
  ASSERT_TRUE(dynamics[0] && dynamics[1] && dynamics[2]);

  using Matrix = std::vector<std::vector<Rational>>;
  const model::AffineDynamics& turn = *dynamics[0];
  EXPECT_EQ(turn.matrix, (Matrix{{2, 3}, {Rational(-1, 4), Rational(1, 4)}}));
  EXPECT_EQ(turn.offset, (std::vector<Rational>{-1, Rational(1, 2)}));
  using Kind = model::DisturbanceModel::Kind;
  ASSERT_EQ(turn.disturbance.size(), 2U);
  EXPECT_EQ(turn.disturbance[0].kind, Kind::Bounded);  // from the model level
  EXPECT_EQ(turn.disturbance[0].first, Rational(-3, 10));
  EXPECT_EQ(turn.disturbance[0].second, Rational(3, 10));
  EXPECT_EQ(turn.disturbance[1].kind, Kind::Gaussian);  // from the block
  EXPECT_EQ(turn.disturbance[1].first, 0);
  EXPECT_EQ(turn.disturbance[1].second, Rational(1, 20));

  const model::AffineDynamics& stop = *dynamics[1];  // unmentioned: x' = x
  EXPECT_EQ(stop.matrix, (Matrix{{1, 0}, {0, 1}}));
  EXPECT_EQ(stop.offset, (std::vector<Rational>{0, 0}));
  EXPECT_EQ(stop.disturbance[0].kind, Kind::Bounded);
  EXPECT_EQ(stop.disturbance[1].kind, Kind::None);

  const model::AffineDynamics& drift = *dynamics[2];
  EXPECT_EQ(drift.matrix, (Matrix{{1, 0}, {1, 0}}));
  ASSERT_TRUE(ir.period);
  EXPECT_EQ(*ir.period, Rational(1, 5));
}

TEST(Checker, ContextDynamicsReplaceTheBaseForTheirAction) {
  const ModelIR ir = expect_ok(with_catalog(
      "mdp m {\n"
      "  continuous x : [0 .. 1];\n"
      "  actions go, stop;\n"
      "  dynamics [go] { x' = x + 0.1; }\n"
      "  dynamics [stop] { }\n"
      "}\n",
      "context fast { dynamics [go] { x' = x + 0.2; disturbance x in [0 .. 0.01]; } }\n"
      "context normal = base;\n"
      "switching stay 0.5;"));
  ASSERT_EQ(ir.contexts.size(), 2U);
  EXPECT_EQ(ir.contexts[0].dynamics[0]->offset[0], Rational(1, 5));
  EXPECT_EQ(ir.contexts[0].dynamics[0]->disturbance[0].second, Rational(1, 100));
  EXPECT_EQ(ir.contexts[0].dynamics[1]->offset[0], 0);  // `stop` as in the base
  EXPECT_EQ(ir.contexts[1].dynamics[0]->offset[0], Rational(1, 10));
}

// A model-level disturbance holds for every action: the model's blocks, a context's own
// blocks (unless they say otherwise), and actions left to `default self;`.
TEST(Checker, ModelDisturbanceHoldsForEveryAction) {
  using Kind = model::DisturbanceModel::Kind;
  const ModelIR ir = expect_ok(
      with_catalog("mdp m {\n"
                   "  continuous x : [0 .. 1];\n"
                   "  continuous y : [0 .. 1];\n"
                   "  actions go, stop, turn;\n"
                   "  default self;\n"
                   "  disturbance x in [-0.1 .. 0.1];\n"
                   "  dynamics [go] { x' = x + 0.1; }\n"
                   "}\n",
                   "context windy { dynamics [go] { x' = x + 0.2; } dynamics [turn] { y' = 1 - y;\n"
                   "    disturbance x ~ gaussian(0, 0.5); } }\n"
                   "context calm = base;\n"
                   "switching stay 0.5;"));
  for (const auto& context : ir.contexts) {
    for (std::size_t a = 0; a < 3; ++a) {
      ASSERT_TRUE(context.dynamics[a]) << context.name << " action " << a;
      EXPECT_EQ(context.dynamics[a]->disturbance[1].kind, Kind::None);  // y is never disturbed
    }
  }
  const auto& windy = ir.contexts[0].dynamics;
  EXPECT_EQ(windy[0]->offset[0], Rational(1, 5));
  EXPECT_EQ(windy[0]->disturbance[0].kind, Kind::Bounded);  // the context's block, model's noise
  EXPECT_EQ(windy[0]->disturbance[0].second, Rational(1, 10));
  EXPECT_EQ(windy[2]->disturbance[0].kind, Kind::Gaussian);  // the block's own wins
  const auto& calm = ir.contexts[1].dynamics;
  EXPECT_EQ(calm[1]->matrix[0][0], 1);                     // `stop` has no block: x' = x
  EXPECT_EQ(calm[1]->disturbance[0].kind, Kind::Bounded);  // ... and is disturbed too
  EXPECT_EQ(calm[1]->disturbance[0].first, Rational(-1, 10));
}

TEST(Checker, MissingDynamicsWithDefaultSelf) {
  const ModelIR ir = expect_ok(continuous_model("dynamics [go] { x' = 0.5 * x; }"));
  EXPECT_EQ(ir.missing, model::MissingPolicy::SelfLoop);
  ASSERT_TRUE(ir.contexts[0].dynamics[0]);
}

TEST(Checker, RegionsAreLinearConstraints) {
  const ModelIR ir =
      expect_ok(continuous_model("region box = x >= 0.3 & x <= 0.8 & y > -1;\n"
                                 "region line = 2 * x - y == 1 / 2;\n"
                                 "region both = box & line & true;\n"
                                 "reward box & x < 0.5 : 1;\n"));
  ASSERT_EQ(ir.regions.size(), 3U);
  using model::LinearConstraint;
  auto is = [](const LinearConstraint& c, std::vector<Rational> coefficients, Rational bound,
               bool strict) {
    return c.coefficients == coefficients && c.bound == bound && c.strict == strict;
  };
  const auto& box = ir.regions[0].constraints;
  EXPECT_EQ(ir.regions[0].name, "box");
  ASSERT_EQ(box.size(), 3U);
  EXPECT_TRUE(is(box[0], {-1, 0}, Rational(-3, 10), false));  // -x <= -0.3
  EXPECT_TRUE(is(box[1], {1, 0}, Rational(4, 5), false));     //  x <= 0.8
  EXPECT_TRUE(is(box[2], {0, -1}, 1, true));                  // -y < 1
  const auto& line = ir.regions[1].constraints;
  ASSERT_EQ(line.size(), 2U);  // == is two inequalities
  EXPECT_TRUE(is(line[0], {2, -1}, Rational(1, 2), false));
  EXPECT_TRUE(is(line[1], {-2, 1}, Rational(-1, 2), false));
  EXPECT_EQ(ir.regions[2].constraints.size(), 5U);  // box, then line; `true` adds nothing
  ASSERT_EQ(ir.contexts[0].rewards.size(), 1U);
}

TEST(Checker, ShippedSpecsCheck) {
  for (const char* name : {"discrete_tracking", "go1_treat"}) {
    SourceManager sources;
    std::ostringstream out;
    DiagnosticEngine diagnostics(sources, out);
    const auto ir = load_spec(std::string(OASIS_SOURCE_DIR) + "/specs/" + name + ".oasis", sources,
                              diagnostics);
    EXPECT_TRUE(ir) << out.str();
    EXPECT_EQ(diagnostics.error_count(), 0U) << out.str();
  }
}

TEST(Checker, Go1TreatSpec) {
  SourceManager sources;
  std::ostringstream out;
  DiagnosticEngine diagnostics(sources, out);
  const auto ir =
      load_spec(std::string(OASIS_SOURCE_DIR) + "/specs/go1_treat.oasis", sources, diagnostics);
  ASSERT_TRUE(ir) << out.str();
  EXPECT_EQ(ir->kind, ModelKind::Continuous);
  EXPECT_EQ(ir->continuous.size(), 4U);
  EXPECT_EQ(ir->actions.size(), 6U);
  EXPECT_EQ(ir->regions.size(), 2U);
  EXPECT_EQ(ir->regions[0].constraints.size(), 4U);
  ASSERT_EQ(ir->contexts.size(), 2U);
  // left: x1' = 0.995 x1 + 0.0998 y1, y1' = -0.0998 x1 + 0.995 y1 (exactly).
  const auto& left = *ir->contexts[0].dynamics[0];
  EXPECT_EQ(left.matrix[0][0], q(995, 1000));
  EXPECT_EQ(left.matrix[0][1], q(998, 10000));
  EXPECT_EQ(left.matrix[1][0], q(-998, 10000));
  EXPECT_EQ(left.matrix[2][2], q(995, 1000));
  EXPECT_EQ(left.matrix[0][2], 0);
  // Every action gets the model-level disturbance of every variable.
  for (const auto& dynamics : ir->contexts[0].dynamics) {
    ASSERT_TRUE(dynamics);
    for (const auto& d : dynamics->disturbance) {
      EXPECT_EQ(d.kind, model::DisturbanceModel::Kind::Bounded);
      EXPECT_EQ(d.second, Rational(3, 10));
    }
  }
  EXPECT_EQ(ir->switching.matrix, (std::vector<Rational>{Rational(4, 5), Rational(1, 5),
                                                         Rational(1, 5), Rational(4, 5)}));
  EXPECT_EQ(*ir->objective.discount, Rational(19, 20));
}

}  // namespace
}  // namespace oasis::frontend
