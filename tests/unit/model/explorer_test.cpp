// Unit tests of exploration (compiler/model/explorer.cpp): from a checked spec to the explicit
// model. Exact probabilities and rewards of the shipped discrete example, state and
// transition counts of small factored specs, deterministic breadth-first numbering, missing
// transition policies, state-dependent probabilities, and the errors exploration reports.
// Every model explored here must pass model::find_structural_problem.

#include "model/explorer.hpp"

#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "frontend/load_spec.hpp"

namespace oasis::model {
namespace {

// An exact rational in canonical form (mpq_class(2, 4) is not reduced).
Rational q(long numerator, long denominator) {
  Rational value(numerator, denominator);
  value.canonicalize();
  return value;
}

// The front end and exploration of one spec; the sources stay alive for diagnostics.
struct Explored {
  SourceManager sources;
  std::ostringstream out;
  DiagnosticEngine diagnostics{sources, out};
  std::optional<ModelIR> ir;
  std::optional<ExplicitModel> model;

  [[nodiscard]] std::string output() const { return out.str(); }
  [[nodiscard]] bool reported(const std::string& text) const {
    return output().find(text) != std::string::npos;
  }
};

std::unique_ptr<Explored> explore_text(std::string text, const ExploreOptions& options = {}) {
  auto explored = std::make_unique<Explored>();
  const FileId file = explored->sources.add("explore.oasis", std::move(text));
  explored->ir = frontend::check_spec_text(file, explored->diagnostics);
  if (explored->ir) explored->model = explore(*explored->ir, explored->diagnostics, options);
  if (explored->model) {
    // Whatever the spec, an explored model is structurally sound.
    const auto problem = find_structural_problem(*explored->model);
    EXPECT_FALSE(problem) << *problem;
    EXPECT_EQ(explored->diagnostics.error_count(), 0U) << explored->output();
  } else {
    EXPECT_GT(explored->diagnostics.error_count(), 0U) << "no model, yet no error";
  }
  return explored;
}

std::unique_ptr<Explored> explore_file(const std::string& name) {
  auto explored = std::make_unique<Explored>();
  explored->ir = frontend::load_spec(std::string(OASIS_SOURCE_DIR) + "/specs/" + name,
                                     explored->sources, explored->diagnostics);
  if (explored->ir) explored->model = explore(*explored->ir, explored->diagnostics);
  if (explored->model) {
    EXPECT_FALSE(find_structural_problem(*explored->model));
  }
  return explored;
}

// The distribution of (s, a) in a context, by target name.
using Row = std::map<std::string, Rational>;
Row row(const ExplicitModel& model, std::size_t context, StateIndex s, ActionIndex a) {
  const TransitionMatrix& matrix = *model.contexts.at(context).transitions;
  Row result;
  for (EdgeIndex e = matrix.edges_begin(s, a); e < matrix.edges_end(s, a); ++e) {
    result[model.states.name(matrix.edge_target[e])] = model.values[matrix.edge_probability[e]];
  }
  return result;
}

StateIndex state_named(const ExplicitModel& model, const std::string& name) {
  for (StateIndex s = 0; s < model.num_states(); ++s) {
    if (model.states.name(s) == name) return s;
  }
  ADD_FAILURE() << "no state " << name;
  return 0;
}

std::vector<std::string> state_names(const ExplicitModel& model) {
  std::vector<std::string> names;
  for (StateIndex s = 0; s < model.num_states(); ++s)
    names.push_back(model.states.name(s));
  return names;
}

// ---- the shipped discrete example -----------------------------------------------------------

TEST(ExploreDiscreteTracking, StatesActionsContexts) {
  const auto explored = explore_file("discrete_tracking.oasis");
  ASSERT_TRUE(explored->model) << explored->output();
  const ExplicitModel& model = *explored->model;
  EXPECT_EQ(model.name, "discrete_tracking");
  EXPECT_EQ(model.num_states(), 3U);
  EXPECT_EQ(state_names(model), (std::vector<std::string>{"s1", "s2", "s3"}));
  EXPECT_EQ(model.actions, (std::vector<std::string>{"L", "R"}));
  EXPECT_EQ(model.states.initial, std::vector<StateIndex>{1});  // init s2
  ASSERT_EQ(model.contexts.size(), 2U);
  EXPECT_EQ(model.contexts[0].name, "object_at_s3");
  EXPECT_EQ(model.contexts[1].name, "object_at_s1");
  // The contexts change only rewards, so they share one transition matrix.
  EXPECT_EQ(model.contexts[0].transitions, model.contexts[1].transitions);
  EXPECT_EQ(explored->diagnostics.error_count(), 0U);
}

TEST(ExploreDiscreteTracking, ExactProbabilities) {
  const auto explored = explore_file("discrete_tracking.oasis");
  ASSERT_TRUE(explored->model) << explored->output();
  const ExplicitModel& model = *explored->model;
  const Rational half(1, 2);
  for (std::size_t c = 0; c < 2; ++c) {
    EXPECT_EQ(row(model, c, 0, 0), (Row{{"s1", 1}}));
    EXPECT_EQ(row(model, c, 1, 0), (Row{{"s1", half}, {"s2", half}}));
    EXPECT_EQ(row(model, c, 2, 0), (Row{{"s1", half}, {"s2", half}}));
    EXPECT_EQ(row(model, c, 0, 1), (Row{{"s2", half}, {"s3", half}}));
    EXPECT_EQ(row(model, c, 1, 1), (Row{{"s2", half}, {"s3", half}}));
    EXPECT_EQ(row(model, c, 2, 1), (Row{{"s3", 1}}));
  }
  const TransitionMatrix& matrix = *model.contexts[0].transitions;
  EXPECT_EQ(matrix.num_edges(), 10U);
  EXPECT_EQ(matrix.num_enabled_choices(), 6U);
  // 1/2 is stored once in the pool; every edge refers to it by the same id.
  std::set<ValueId> ids(matrix.edge_probability.begin(), matrix.edge_probability.end());
  EXPECT_EQ(ids.size(), 2U);  // 1 and 1/2
}

TEST(ExploreDiscreteTracking, ExactRewardsSwitchingAndObjective) {
  const auto explored = explore_file("discrete_tracking.oasis");
  ASSERT_TRUE(explored->model) << explored->output();
  const ExplicitModel& model = *explored->model;
  for (ActionIndex a = 0; a < 2; ++a) {
    // object_at_s3 rewards s3; object_at_s1 rewards s1; only state rewards.
    EXPECT_EQ(model.reward(0, 0, a), 0);
    EXPECT_EQ(model.reward(0, 1, a), 0);
    EXPECT_EQ(model.reward(0, 2, a), 1);
    EXPECT_EQ(model.reward(1, 0, a), 1);
    EXPECT_EQ(model.reward(1, 1, a), 0);
    EXPECT_EQ(model.reward(1, 2, a), 0);
  }
  EXPECT_TRUE(model.contexts[0].rewards.choice.empty());
  EXPECT_EQ(model.switching.matrix, (std::vector<Rational>{q(4, 5), q(1, 5), q(1, 5), q(4, 5)}));
  EXPECT_EQ(model.switching.prior, (std::vector<Rational>{q(1, 2), q(1, 2)}));
  ASSERT_TRUE(model.objective.discount);
  EXPECT_EQ(*model.objective.discount, q(9, 10));
  EXPECT_FALSE(model.objective.horizon);
}

// ---- explicit models ------------------------------------------------------------------------

TEST(ExploreExplicit, KeepsEveryDeclaredStateInOrder) {
  const auto explored = explore_text(
      "mdp m {\n"
      "  states a, b, island;\n"
      "  actions go;\n"
      "  init b, a;\n"
      "  default disabled;\n"
      "  a, go -> b;\n"
      "  b, go -> 1/3: a + 2/3: b;\n"
      "}\n");
  ASSERT_TRUE(explored->model) << explored->output();
  const ExplicitModel& model = *explored->model;
  EXPECT_EQ(state_names(model), (std::vector<std::string>{"a", "b", "island"}));
  EXPECT_EQ(model.states.initial, (std::vector<StateIndex>{1, 0}));
  EXPECT_EQ(row(model, 0, 1, 0), (Row{{"a", q(1, 3)}, {"b", q(2, 3)}}));
  EXPECT_FALSE(model.contexts[0].transitions->enabled(2, 0));
}

TEST(ExploreExplicit, DefaultSelfAddsSelfLoops) {
  const std::string body =
      "  states a, b;\n"
      "  actions go, wait;\n"
      "  a, go -> b;\n"
      "  b, go -> a;\n"
      "  a, wait -> 1/2: a + 1/2: b;\n"
      "}\n";
  const auto self = explore_text("mdp m {\n  default self;\n" + body);
  ASSERT_TRUE(self->model) << self->output();
  EXPECT_EQ(row(*self->model, 0, 1, 1), (Row{{"b", 1}}));  // b, wait: stays
  EXPECT_EQ(self->model->contexts[0].transitions->num_enabled_choices(), 4U);

  const auto disabled = explore_text("mdp m {\n  default disabled;\n" + body);
  ASSERT_TRUE(disabled->model) << disabled->output();
  EXPECT_FALSE(disabled->model->contexts[0].transitions->enabled(1, 1));
  EXPECT_TRUE(disabled->model->contexts[0].transitions->enabled(0, 1));
  EXPECT_EQ(disabled->model->contexts[0].transitions->num_enabled_choices(), 3U);
  EXPECT_EQ(disabled->model->contexts[0].transitions->num_edges(), 4U);
}

TEST(ExploreExplicit, ContextOverridesOneTransition) {
  const auto explored = explore_text(
      "mdp m {\n"
      "  states a, b;\n"
      "  actions go;\n"
      "  a, go -> b;\n"
      "  b, go -> a;\n"
      "  reward a : 1;\n"
      "}\n"
      "catalog {\n"
      "  context plain = base;\n"
      "  context slippery { a, go -> 0.25: a + 0.75: b; reward [go] b : 2; }\n"
      "  switching { plain -> 0.9: plain + 0.1: slippery; slippery -> slippery; }\n"
      "  prior 1: plain;\n"
      "}\n");
  ASSERT_TRUE(explored->model) << explored->output();
  const ExplicitModel& model = *explored->model;
  ASSERT_EQ(model.contexts.size(), 2U);
  EXPECT_NE(model.contexts[0].transitions, model.contexts[1].transitions);
  EXPECT_EQ(row(model, 0, 0, 0), (Row{{"b", 1}}));
  EXPECT_EQ(row(model, 1, 0, 0), (Row{{"a", q(1, 4)}, {"b", q(3, 4)}}));
  EXPECT_EQ(row(model, 1, 1, 0), (Row{{"a", 1}}));  // not overridden
  EXPECT_EQ(model.reward(0, 0, 0), 1);
  EXPECT_EQ(model.reward(1, 0, 0), 0);  // the context's rewards replace the base's
  EXPECT_EQ(model.reward(1, 1, 0), 2);
  EXPECT_EQ(model.switching.matrix, (std::vector<Rational>{q(9, 10), q(1, 10), 0, 1}));
  EXPECT_EQ(model.switching.prior, (std::vector<Rational>{1, 0}));
}

TEST(ExploreExplicit, StateLimit) {
  ExploreOptions options;
  options.max_states = 2;
  const auto explored =
      explore_text("mdp m { states a, b, c; actions go; default self; }", options);
  EXPECT_FALSE(explored->model);
  EXPECT_TRUE(
      explored->reported("error: model lists 3 states, more than the limit of 2 (raise "
                         "it with --max-states)"))
      << explored->output();
}

// ---- factored models: counts and numbering --------------------------------------------------

std::string grid(int n, const char* missing) {
  return "mdp grid {\n"
         "  const N = " +
         std::to_string(n) +
         ";\n"
         "  var x : [0 .. N-1];\n"
         "  var y : [0 .. N-1];\n"
         "  actions right, up, reset;\n"
         "  default " +
         missing +
         ";\n"
         "  [right] x < N-1 -> 0.9: (x' = x + 1) + 0.1: true;\n"
         "  [up] y < N-1 -> (y' = y + 1);\n"
         "  [reset] x == N-1 & y == N-1 -> (x' = 0) & (y' = 0);\n"
         "  reward x == N-1 & y == N-1 : 1;\n"
         "}\n";
}

TEST(ExploreFactored, GridCounts) {
  for (const std::uint32_t n : {1U, 2U, 5U, 30U}) {
    SCOPED_TRACE("N = " + std::to_string(n));
    const auto disabled = explore_text(grid(static_cast<int>(n), "disabled"));
    ASSERT_TRUE(disabled->model) << disabled->output();
    const TransitionMatrix& matrix = *disabled->model->contexts[0].transitions;
    EXPECT_EQ(disabled->model->num_states(), n * n);
    // right: N(N-1) choices of 2 edges; up: N(N-1) of 1; reset: 1 of 1.
    EXPECT_EQ(matrix.num_enabled_choices(), 2 * n * (n - 1) + 1);
    EXPECT_EQ(matrix.num_edges(), 3 * n * (n - 1) + 1);

    const auto self = explore_text(grid(static_cast<int>(n), "self"));
    ASSERT_TRUE(self->model) << self->output();
    const TransitionMatrix& looped = *self->model->contexts[0].transitions;
    EXPECT_EQ(self->model->num_states(), n * n);
    EXPECT_EQ(looped.num_enabled_choices(), 3 * n * n);
    // Plus a self-loop where an action is disabled: N for right, N for up, N^2-1 for reset.
    EXPECT_EQ(looped.num_edges(), 3 * n * (n - 1) + 1 + 2 * n + (n * n - 1));
  }
}

TEST(ExploreFactored, GridProbabilitiesAndRewards) {
  const auto explored = explore_text(grid(3, "disabled"));
  ASSERT_TRUE(explored->model) << explored->output();
  const ExplicitModel& model = *explored->model;
  const StateIndex s = state_named(model, "(x=1,y=2)");
  EXPECT_EQ(row(model, 0, s, 0), (Row{{"(x=1,y=2)", q(1, 10)}, {"(x=2,y=2)", q(9, 10)}}));
  EXPECT_FALSE(model.contexts[0].transitions->enabled(s, 1));
  const StateIndex corner = state_named(model, "(x=2,y=2)");
  EXPECT_EQ(row(model, 0, corner, 2), (Row{{"(x=0,y=0)", 1}}));
  EXPECT_EQ(model.reward(0, corner, 0), 1);
  EXPECT_EQ(model.reward(0, s, 0), 0);
  EXPECT_EQ(model.states.variables, (std::vector<std::string>{"x", "y"}));
}

TEST(ExploreFactored, BreadthFirstNumbering) {
  const auto explored = explore_text(grid(4, "disabled"));
  ASSERT_TRUE(explored->model) << explored->output();
  const ExplicitModel& model = *explored->model;
  EXPECT_EQ(model.states.initial, std::vector<StateIndex>{0});
  // From (0,0): `right` finds (1,0), then `up` finds (0,1); from (1,0): (2,0), (1,1); ...
  const std::vector<std::string> names = state_names(model);
  ASSERT_GE(names.size(), 6U);
  EXPECT_EQ(std::vector<std::string>(names.begin(), names.begin() + 6),
            (std::vector<std::string>{"(x=0,y=0)", "(x=1,y=0)", "(x=0,y=1)", "(x=2,y=0)",
                                      "(x=1,y=1)", "(x=0,y=2)"}));
  // Breadth-first: the distance from the initial state never decreases with the index.
  const TransitionMatrix& matrix = *model.contexts[0].transitions;
  std::vector<int> distance(model.num_states(), -1);
  distance[0] = 0;
  for (StateIndex s = 0; s < model.num_states(); ++s) {
    ASSERT_GE(distance[s], 0) << "state " << s << " numbered before it was reached";
    if (s > 0) {
      EXPECT_GE(distance[s], distance[s - 1]);
    }
    for (ActionIndex a = 0; a < model.num_actions(); ++a) {
      for (EdgeIndex e = matrix.edges_begin(s, a); e < matrix.edges_end(s, a); ++e) {
        if (distance[matrix.edge_target[e]] < 0) distance[matrix.edge_target[e]] = distance[s] + 1;
      }
    }
  }
}

TEST(ExploreFactored, NumberingIsDeterministic) {
  const auto first = explore_text(grid(7, "self"));
  const auto second = explore_text(grid(7, "self"));
  ASSERT_TRUE(first->model && second->model);
  EXPECT_EQ(first->model->states.valuations, second->model->states.valuations);
  const TransitionMatrix& a = *first->model->contexts[0].transitions;
  const TransitionMatrix& b = *second->model->contexts[0].transitions;
  EXPECT_EQ(a.choice_begin, b.choice_begin);
  EXPECT_EQ(a.edge_target, b.edge_target);
  EXPECT_EQ(a.edge_probability, b.edge_probability);
}

TEST(ExploreFactored, OnlyReachableStates) {
  const auto explored = explore_text(
      "mdp counter {\n"
      "  var x : [0 .. 10];\n"
      "  var y : [0 .. 7] init 3;\n"
      "  actions step;\n"
      "  [step] true -> (x' = min(x + 2, 10));\n"
      "}\n");
  ASSERT_TRUE(explored->model) << explored->output();
  EXPECT_EQ(state_names(*explored->model),
            (std::vector<std::string>{"(x=0,y=3)", "(x=2,y=3)", "(x=4,y=3)", "(x=6,y=3)",
                                      "(x=8,y=3)", "(x=10,y=3)"}));
  EXPECT_EQ(explored->model->contexts[0].transitions->num_edges(), 6U);
  EXPECT_EQ(row(*explored->model, 0, 5, 0), (Row{{"(x=10,y=3)", 1}}));
}

TEST(ExploreFactored, ContextsReachMoreStatesTogether) {
  // The state space is what any context reaches; each context has its own transitions.
  const auto explored = explore_text(
      "mdp m {\n"
      "  var x : [0 .. 10];\n"
      "  actions go;\n"
      "  default self;\n"
      "  [go] x < 2 -> (x' = x + 1);\n"
      "}\n"
      "catalog {\n"
      "  context slow = base;\n"
      "  context fast { [go] x < 4 -> (x' = x + 1); }\n"
      "  switching stay 0.5;\n"
      "}\n");
  ASSERT_TRUE(explored->model) << explored->output();
  const ExplicitModel& model = *explored->model;
  EXPECT_EQ(model.num_states(), 5U);
  const StateIndex three = state_named(model, "(x=3)");
  EXPECT_EQ(row(model, 0, three, 0), (Row{{"(x=3)", 1}}));  // slow: stuck from 2 on
  EXPECT_EQ(row(model, 1, three, 0), (Row{{"(x=4)", 1}}));
  EXPECT_EQ(row(model, 0, state_named(model, "(x=2)"), 0), (Row{{"(x=2)", 1}}));
  EXPECT_EQ(row(model, 1, state_named(model, "(x=2)"), 0), (Row{{"(x=3)", 1}}));
}

TEST(ExploreFactored, OnlyStatesSomeContextReaches) {
  // Every context replaces the model's `go`, so the model's own commands describe no
  // context: the states only they reach (x = 2 .. 5) are in no context's state space.
  const auto explored = explore_text(
      "mdp m {\n"
      "  var x : [0 .. 10];\n"
      "  actions go;\n"
      "  default self;\n"
      "  [go] x < 5 -> (x' = x + 1);\n"
      "}\n"
      "catalog {\n"
      "  context slow { [go] x < 1 -> (x' = x + 1); }\n"
      "  context stuck { [go] true -> true; }\n"
      "  switching stay 0.5;\n"
      "}\n");
  ASSERT_TRUE(explored->model) << explored->output();
  EXPECT_EQ(state_names(*explored->model), (std::vector<std::string>{"(x=0)", "(x=1)"}));
  EXPECT_EQ(row(*explored->model, 0, 1, 0), (Row{{"(x=1)", 1}}));
}

TEST(ExploreFactored, StateAndChoiceRewardsAddUp) {
  const auto explored = explore_text(
      "mdp m {\n"
      "  var x : [0 .. 2];\n"
      "  actions inc, dec;\n"
      "  default self;\n"
      "  [inc] x < 2 -> (x' = x + 1);\n"
      "  [dec] x > 0 -> (x' = x - 1);\n"
      "  reward x == 1 : 2;\n"
      "  reward x >= 1 : x * 3 / 2;\n"
      "  reward [inc] true : -1/10;\n"
      "}\n");
  ASSERT_TRUE(explored->model) << explored->output();
  const ExplicitModel& model = *explored->model;
  const StateIndex zero = state_named(model, "(x=0)");
  const StateIndex one = state_named(model, "(x=1)");
  const StateIndex two = state_named(model, "(x=2)");
  EXPECT_EQ(model.reward(0, zero, 0), q(-1, 10));
  EXPECT_EQ(model.reward(0, zero, 1), 0);
  EXPECT_EQ(model.reward(0, one, 0), q(7, 2) - q(1, 10));
  EXPECT_EQ(model.reward(0, one, 1), q(7, 2));
  EXPECT_EQ(model.reward(0, two, 1), 3);
  EXPECT_EQ(model.contexts[0].rewards.choice.size(), 3U * 2U);
}

TEST(ExploreFactored, MissingTransitionPolicies) {
  const std::string body =
      "  var x : [0 .. 3];\n"
      "  actions inc, dec;\n"
      "  [inc] x < 3 -> (x' = x + 1);\n"
      "  [dec] x > 0 -> (x' = x - 1);\n"
      "}\n";
  const auto self = explore_text("mdp m {\n  default self;\n" + body);
  ASSERT_TRUE(self->model) << self->output();
  const TransitionMatrix& looped = *self->model->contexts[0].transitions;
  EXPECT_EQ(looped.num_enabled_choices(), 8U);
  EXPECT_EQ(looped.num_edges(), 8U);
  EXPECT_EQ(row(*self->model, 0, state_named(*self->model, "(x=3)"), 0), (Row{{"(x=3)", 1}}));

  const auto disabled = explore_text("mdp m {\n  default disabled;\n" + body);
  ASSERT_TRUE(disabled->model) << disabled->output();
  const TransitionMatrix& partial = *disabled->model->contexts[0].transitions;
  EXPECT_EQ(partial.num_enabled_choices(), 6U);
  EXPECT_FALSE(partial.enabled(state_named(*disabled->model, "(x=3)"), 0));
  EXPECT_FALSE(partial.enabled(state_named(*disabled->model, "(x=0)"), 1));

  const auto error = explore_text("mdp m {\n" + body);
  EXPECT_FALSE(error->model);
  EXPECT_TRUE(error->reported(
      "error: in state (x=0) no command of action 'dec' is enabled (add one, or write 'default "
      "self;' or 'default disabled;' in the model)"))
      << error->output();
}

// ---- state-dependent probabilities ----------------------------------------------------------

TEST(ExploreProbabilities, StateDependentAreExact) {
  const auto explored = explore_text(
      "mdp walk {\n"
      "  var x : [0 .. 10] init 5;\n"
      "  actions move;\n"
      "  [move] true -> x/10 : (x' = max(x - 1, 0)) + (10 - x)/10 : (x' = min(x + 1, 10));\n"
      "}\n");
  ASSERT_TRUE(explored->model) << explored->output();
  const ExplicitModel& model = *explored->model;
  EXPECT_EQ(model.num_states(), 11U);
  EXPECT_EQ(row(model, 0, state_named(model, "(x=5)"), 0),
            (Row{{"(x=4)", q(1, 2)}, {"(x=6)", q(1, 2)}}));
  EXPECT_EQ(row(model, 0, state_named(model, "(x=3)"), 0),
            (Row{{"(x=2)", q(3, 10)}, {"(x=4)", q(7, 10)}}));
  // A probability 0 gives no edge.
  EXPECT_EQ(row(model, 0, state_named(model, "(x=0)"), 0), (Row{{"(x=1)", 1}}));
  EXPECT_EQ(row(model, 0, state_named(model, "(x=10)"), 0), (Row{{"(x=9)", 1}}));
}

TEST(ExploreProbabilities, OutcomesWithOneTargetAreMerged) {
  const auto explored = explore_text(
      "mdp m {\n"
      "  var x : [0 .. 4] init 2;\n"
      "  actions go;\n"
      "  [go] true -> x/4 : (x' = 2) + 1/4 : (x' = 2) + (3 - x)/4 : (x' = 2);\n"
      "}\n");
  ASSERT_TRUE(explored->model) << explored->output();
  EXPECT_EQ(explored->model->num_states(), 1U);
  EXPECT_EQ(row(*explored->model, 0, 0, 0), (Row{{"(x=2)", 1}}));
  EXPECT_EQ(explored->model->contexts[0].transitions->num_edges(), 1U);
}

TEST(ExploreProbabilities, SumNotOneIsReportedWithTheState) {
  // Sums to 1 in the initial state x = 5, not in x = 0, which it reaches.
  const auto explored = explore_text(
      "mdp m {\n"
      "  var x : [0 .. 10] init 5;\n"
      "  actions go;\n"
      "  [go] true -> x/10 : (x' = 0) + 1/2 : (x' = 1);\n"
      "}\n");
  EXPECT_FALSE(explored->model);
  EXPECT_TRUE(explored->reported(
      "explore.oasis:4:3: error: in state (x=0) the probabilities sum to 1/2 (0.5), not 1"))
      << explored->output();
}

TEST(ExploreProbabilities, SumNotOneIsReportedWhateverTheOrderOfOutcomes) {
  // The same with the constant outcome first.
  const auto explored = explore_text(
      "mdp m {\n"
      "  var x : [0 .. 10] init 5;\n"
      "  actions go;\n"
      "  [go] true -> 1/2 : (x' = 1) + x/10 : (x' = 0);\n"
      "}\n");
  EXPECT_FALSE(explored->model);
  EXPECT_TRUE(explored->reported("error: in state (x=1) the probabilities sum to 3/5 (0.6), not 1"))
      << explored->output();
}

TEST(ExploreProbabilities, NegativeOrAboveOneInAState) {
  const auto negative = explore_text(
      "mdp m {\n"
      "  var x : [0 .. 10] init 5;\n"
      "  actions go;\n"
      "  [go] true -> (x - 5)/10 : (x' = 0) + (15 - x)/10 : (x' = 1);\n"
      "}\n");
  EXPECT_FALSE(negative->model);
  EXPECT_TRUE(negative->reported(
      "explore.oasis:4:16: error: probability -2/5 (-0.4) in state (x=1) is negative"))
      << negative->output();

  const auto above = explore_text(
      "mdp m {\n"
      "  var x : [0 .. 10];\n"
      "  actions go;\n"
      "  [go] true -> (x + 2)/5 : (x' = x + 1) + (3 - x)/5 : (x' = 0);\n"
      "}\n");
  EXPECT_FALSE(above->model);
  EXPECT_TRUE(above->reported("error: probability 6/5 (1.2) in state (x=4) is greater than 1"))
      << above->output();
}

// ---- errors ---------------------------------------------------------------------------------

TEST(ExploreErrors, StateLimit) {
  ExploreOptions options;
  options.max_states = 50;
  const auto explored = explore_text(grid(100, "self"), options);
  EXPECT_FALSE(explored->model);
  EXPECT_EQ(explored->diagnostics.error_count(), 1U);
  EXPECT_TRUE(explored->reported(
      "error: exploration passed the limit of 50 states (raise it with --max-states)"))
      << explored->output();

  options.max_states = 25;  // exactly the 5 x 5 grid
  EXPECT_TRUE(explore_text(grid(5, "self"), options)->model);
  options.max_states = 24;
  EXPECT_FALSE(explore_text(grid(5, "self"), options)->model);
}

TEST(ExploreErrors, StateLimitOnAHugeSpace) {
  // 2^40 values per variable: the limit stops exploration long before memory runs out.
  ExploreOptions options;
  options.max_states = 1000;
  const auto explored = explore_text(
      "mdp big {\n"
      "  var x : [0 .. 1099511627775];\n"
      "  var y : [0 .. 1099511627775];\n"
      "  actions go;\n"
      "  [go] true -> 1/2: (x' = mod(x + 1, 1099511627776)) + 1/2: (y' = mod(y * 3 + 1, "
      "1099511627776));\n"
      "}\n",
      options);
  EXPECT_FALSE(explored->model);
  EXPECT_TRUE(explored->reported("exploration passed the limit of 1000 states"))
      << explored->output();
}

TEST(ExploreErrors, IntegerOverflowInAnUpdate) {
  const auto explored = explore_text(
      "mdp m {\n"
      "  var x : [1 .. 10] init 1;\n"
      "  actions go;\n"
      "  [go] true -> (x' = x + 9223372036854775807);\n"
      "}\n");
  EXPECT_FALSE(explored->model);
  EXPECT_TRUE(explored->reported(
      "explore.oasis:4:22: error: integer overflow (values must fit in 64 bits) in state (x=1)"))
      << explored->output();

  const auto product = explore_text(
      "mdp m {\n"
      "  var x : [1 .. 10] init 3;\n"
      "  actions go;\n"
      "  [go] true -> (x' = min(x * 4611686018427387904, 10));\n"
      "}\n");
  EXPECT_FALSE(product->model);
  EXPECT_TRUE(product->reported("integer overflow (values must fit in 64 bits) in state (x=3)"))
      << product->output();
}

TEST(ExploreErrors, EvaluationErrorsInGuardsProbabilitiesAndRewards) {
  const auto guard = explore_text(
      "mdp m {\n"
      "  var x : [0 .. 3];\n"
      "  actions go;\n"
      "  [go] 6 / x > 1 -> true;\n"
      "}\n");
  EXPECT_FALSE(guard->model);
  EXPECT_TRUE(guard->reported("error: division by zero in state (x=0)")) << guard->output();

  const auto probability = explore_text(
      "mdp m {\n"
      "  var x : [0 .. 3] init 1;\n"
      "  actions go;\n"
      "  [go] true -> 1 / x : (x' = 0);\n"
      "}\n");
  EXPECT_FALSE(probability->model);
  EXPECT_TRUE(probability->reported("error: division by zero in state (x=0)"))
      << probability->output();

  const auto reward = explore_text(
      "mdp m {\n"
      "  var x : [0 .. 3] init 1;\n"
      "  actions go;\n"
      "  default self;\n"
      "  reward true : mod(7, x - 1);\n"
      "}\n");
  EXPECT_FALSE(reward->model);
  EXPECT_TRUE(reward->reported("error: mod by zero in state (x=1)")) << reward->output();
}

TEST(ExploreErrors, UpdateOutOfRange) {
  const auto explored = explore_text(
      "mdp counter {\n"
      "  var x : [0 .. 3];\n"
      "  actions up;\n"
      "  [up] true -> (x' = x + 1);\n"
      "}\n");
  EXPECT_FALSE(explored->model);
  EXPECT_TRUE(explored->reported(
      "explore.oasis:4:17: error: update sets 'x' to 4, outside its range [0 .. 3], in state "
      "(x=3)"))
      << explored->output();
}

TEST(ExploreErrors, UpdateOutOfRangeOnlyWhereTheOutcomeIsPossible) {
  // At x = 3 the outcome that would leave the range has probability 0: no edge, no error.
  const auto explored = explore_text(
      "mdp m {\n"
      "  var x : [0 .. 3];\n"
      "  actions up;\n"
      "  [up] true -> (3 - x)/3 : (x' = x + 1) + x/3 : (x' = 0);\n"
      "}\n");
  ASSERT_TRUE(explored->model) << explored->output();
  EXPECT_EQ(explored->model->num_states(), 4U);
}

TEST(ExploreErrors, OverlappingCommands) {
  const auto explored = explore_text(
      "mdp m {\n"
      "  var x : [0 .. 4];\n"
      "  actions step;\n"
      "  [step] x < 3 -> (x' = x + 1);\n"
      "  [step] x >= 2 -> (x' = 0);\n"
      "}\n");
  EXPECT_FALSE(explored->model);
  EXPECT_TRUE(explored->reported(
      "explore.oasis:5:3: error: commands for action 'step' overlap: both are enabled in state "
      "(x=2), which an MDP does not allow"))
      << explored->output();
  EXPECT_TRUE(explored->reported("explore.oasis:4:3: note: the other enabled command"))
      << explored->output();
}

TEST(ExploreErrors, ContinuousModelsAreNotExplored) {
  SourceManager sources;
  std::ostringstream out;
  DiagnosticEngine diagnostics(sources, out);
  const auto ir = frontend::load_spec(std::string(OASIS_SOURCE_DIR) + "/specs/go1_treat.oasis",
                                      sources, diagnostics);
  ASSERT_TRUE(ir) << out.str();
  EXPECT_FALSE(explore(*ir, diagnostics));
  EXPECT_NE(out.str().find("error: model 'go1_treat' has continuous state; it needs the geometry "
                           "layer, not exploration"),
            std::string::npos)
      << out.str();
}

TEST(ExploreProgress, IsReportedForLargeModels) {
  std::uint64_t calls = 0;
  std::uint64_t last_found = 0;
  ExploreOptions options;
  options.progress = [&](std::uint64_t found, std::uint64_t explored) {
    ++calls;
    EXPECT_GE(found, explored);
    last_found = found;
  };
  const auto explored = explore_text(grid(260, "disabled"), options);  // 67600 states
  ASSERT_TRUE(explored->model) << explored->output();
  EXPECT_EQ(calls, 1U);  // every 65536 states
  EXPECT_LE(last_found, 67600U);
}

}  // namespace
}  // namespace oasis::model
