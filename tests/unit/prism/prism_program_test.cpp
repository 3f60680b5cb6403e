// The PRISM-language front end: its semantics (synchronisation, a dtmc's uniform choice, the
// naming of an mdp's choices, renaming, constants, formulas, labels, rewards, initial states)
// on small programs whose explicit models are worked out by hand, and its errors.

#include <algorithm>
#include <map>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "prism/load_program.hpp"

namespace oasis::prism {
namespace {

struct Loaded {
  std::optional<model::ExplicitModel> model;
  std::string messages;
};

Loaded load(const std::string& text, const std::string& constants = "",
            const std::string& rewards = "none") {
  SourceManager sources;
  std::ostringstream out;
  DiagnosticEngine diagnostics(sources, out);
  const FileId file = sources.add("test.pm", text);
  LoadOptions options;
  options.constants = constants;
  options.rewards = *model::LabelSelection::parse(rewards);
  auto model = load_program_text(file, "test", diagnostics, options);
  return {std::move(model), out.str()};
}

model::StateIndex state_named(const model::ExplicitModel& m, const std::string& name) {
  for (model::StateIndex s = 0; s < m.num_states(); ++s) {
    if (m.states.name(s) == name) return s;
  }
  ADD_FAILURE() << "no state " << name;
  return 0;
}

// The distribution of action `action` in state `from`: target name -> probability.
std::map<std::string, Rational> distribution(const model::ExplicitModel& m, const std::string& from,
                                             const std::string& action) {
  const auto a = static_cast<model::ActionIndex>(
      std::find(m.actions.begin(), m.actions.end(), action) - m.actions.begin());
  std::map<std::string, Rational> result;
  if (a == m.num_actions()) {
    ADD_FAILURE() << "no action " << action;
    return result;
  }
  const model::TransitionMatrix& t = *m.contexts.at(0).transitions;
  const model::StateIndex s = state_named(m, from);
  for (model::EdgeIndex e = t.edges_begin(s, a); e < t.edges_end(s, a); ++e)
    result[m.states.name(t.edge_target[e])] = m.values[t.edge_probability[e]];
  return result;
}

std::vector<std::string> labels_of(const model::ExplicitModel& m, const std::string& state) {
  std::vector<std::string> names;
  for (const std::uint32_t l : m.labels.of(state_named(m, state)))
    names.push_back(m.labels.names[l]);
  return names;
}

constexpr const char* kDie = R"(
dtmc
module die
  s : [0..7] init 0;
  d : [0..6] init 0;
  [] s=0 -> 0.5 : (s'=1) + 0.5 : (s'=2);
  [] s=1 -> 0.5 : (s'=3) + 0.5 : (s'=4);
  [] s=2 -> 0.5 : (s'=5) + 0.5 : (s'=6);
  [] s=3 -> 0.5 : (s'=1) + 0.5 : (s'=7) & (d'=1);
  [] s=4 -> 0.5 : (s'=7) & (d'=2) + 0.5 : (s'=7) & (d'=3);
  [] s=5 -> 0.5 : (s'=7) & (d'=4) + 0.5 : (s'=7) & (d'=5);
  [] s=6 -> 0.5 : (s'=2) + 0.5 : (s'=7) & (d'=6);
  [] s=7 -> (s'=7);
endmodule
rewards "coin_flips" [] s<7 : 1; endrewards
label "one" = s=7 & d=1;
)";

TEST(PrismProgram, KnuthYaoDieHasStormsThirteenStatesAndTwentyTransitions) {
  const Loaded loaded = load(kDie);
  ASSERT_TRUE(loaded.model) << loaded.messages;
  const model::ExplicitModel& m = *loaded.model;
  EXPECT_EQ(m.num_states(), 13U);
  EXPECT_EQ(m.contexts.at(0).transitions->num_edges(), 20U);
  EXPECT_EQ(m.actions, std::vector<std::string>{"[0]"});
  EXPECT_EQ(m.states.name(m.states.initial.at(0)), "(s=0,d=0)");
  EXPECT_EQ(labels_of(m, "(s=0,d=0)"), std::vector<std::string>{"init"});
  EXPECT_EQ(labels_of(m, "(s=7,d=1)"), std::vector<std::string>{"one"});
  EXPECT_EQ(distribution(m, "(s=3,d=0)", "[0]"),
            (std::map<std::string, Rational>{{"(s=1,d=0)", Rational(1, 2)},
                                             {"(s=7,d=1)", Rational(1, 2)}}));
  EXPECT_FALSE(model::find_structural_problem(m));
}

TEST(PrismProgram, RewardStructuresBecomeContextsWhenSelected) {
  const Loaded none = load(kDie);
  ASSERT_TRUE(none.model) << none.messages;
  ASSERT_EQ(none.model->contexts.size(), 1U);
  EXPECT_EQ(none.model->contexts[0].name, "default");

  const Loaded all = load(kDie, "", "all");
  ASSERT_TRUE(all.model) << all.messages;
  const model::ExplicitModel& m = *all.model;
  ASSERT_EQ(m.contexts.size(), 1U);
  EXPECT_EQ(m.contexts[0].name, "coin_flips");
  EXPECT_EQ(m.reward(0, state_named(m, "(s=0,d=0)"), 0), 1);
  EXPECT_EQ(m.reward(0, state_named(m, "(s=7,d=1)"), 0), 0);

  const Loaded unknown = load(kDie, "", "flips");
  EXPECT_FALSE(unknown.model);
  EXPECT_NE(unknown.messages.find("no reward structure 'flips' (it has 'coin_flips')"),
            std::string::npos)
      << unknown.messages;
}

TEST(PrismProgram, SynchronisedCommandsMultiplyTheirOutcomes) {
  const Loaded loaded = load(R"(
mdp
module a
  x : [0..1] init 0;
  [go] x=0 -> 1/2 : (x'=1) + 1/2 : true;
endmodule
module b
  y : [0..1] init 0;
  [go] y=0 -> 1/3 : (y'=1) + 2/3 : true;
endmodule
)");
  ASSERT_TRUE(loaded.model) << loaded.messages;
  EXPECT_EQ(distribution(*loaded.model, "(x=0,y=0)", "go"),
            (std::map<std::string, Rational>{{"(x=0,y=0)", Rational(1, 3)},
                                             {"(x=0,y=1)", Rational(1, 6)},
                                             {"(x=1,y=0)", Rational(1, 3)},
                                             {"(x=1,y=1)", Rational(1, 6)}}));
  // Once one module cannot take part, `go` is blocked: (x=1,y=1) is a deadlock.
  EXPECT_EQ(labels_of(*loaded.model, "(x=1,y=1)"), std::vector<std::string>{"deadlock"});
  EXPECT_EQ(labels_of(*loaded.model, "(x=1,y=0)"), std::vector<std::string>{"deadlock"});
}

TEST(PrismProgram, ADtmcTakesItsEnabledCommandsUniformly) {
  const Loaded loaded = load(R"(
dtmc
module m
  x : [0..2] init 0;
  [] x=0 -> (x'=1);
  [] x=0 -> 1/2 : (x'=2) + 1/2 : (x'=1);
  [] x>0 -> true;
endmodule
)");
  ASSERT_TRUE(loaded.model) << loaded.messages;
  EXPECT_EQ(
      distribution(*loaded.model, "(x=0)", "[0]"),
      (std::map<std::string, Rational>{{"(x=1)", Rational(3, 4)}, {"(x=2)", Rational(1, 4)}}));
}

TEST(PrismProgram, AnMdpNamesUnlabelledChoicesByPlaceAndRepeatedLabelsByCount) {
  const Loaded loaded = load(R"(
mdp
module m
  x : [0..3] init 0;
  [] x=0 -> (x'=1);
  [] x=0 -> (x'=2);
  [a] x=0 -> (x'=3);
  [a] x<3 -> (x'=0);
  [] x>0 -> true;
endmodule
)");
  ASSERT_TRUE(loaded.model) << loaded.messages;
  const model::ExplicitModel& m = *loaded.model;
  EXPECT_EQ(distribution(m, "(x=0)", "[0]"), (std::map<std::string, Rational>{{"(x=1)", 1}}));
  EXPECT_EQ(distribution(m, "(x=0)", "[1]"), (std::map<std::string, Rational>{{"(x=2)", 1}}));
  EXPECT_EQ(distribution(m, "(x=0)", "a"), (std::map<std::string, Rational>{{"(x=3)", 1}}));
  EXPECT_EQ(distribution(m, "(x=0)", "a[1]"), (std::map<std::string, Rational>{{"(x=0)", 1}}));
  EXPECT_EQ(m.contexts[0].transitions->num_enabled_choices(), 4U + 2 + 2 + 1);
}

// Actions are numbered as found, so a state may find its choices out of action order: here
// `a` (listed first) is found after `b`, and the unlabelled choice after both. The matrix is
// built as the states are explored, choice indices growing with the actions found.
TEST(PrismProgram, ActionsFoundLaterKeepTheirDistributionsAndRewards) {
  const Loaded loaded = load(R"(
mdp
module m
  x : [0..2] init 0;
  [a] x>0 -> (x'=0);
  [b] x<2 -> 0.5 : (x'=x+1) + 0.5 : (x'=x+1);
  [] x=2 -> 0.25 : (x'=1) + 0.75 : (x'=0);
endmodule
rewards "r" [a] true : 3; [b] x=1 : 1/7; endrewards
)",
                             "", "all");
  ASSERT_TRUE(loaded.model) << loaded.messages;
  const model::ExplicitModel& m = *loaded.model;
  EXPECT_EQ(m.actions, (std::vector<std::string>{"b", "a", "[0]"}));
  EXPECT_EQ(model::find_structural_problem(m), std::nullopt);
  using Distribution = std::map<std::string, Rational>;
  EXPECT_EQ(distribution(m, "(x=0)", "b"), (Distribution{{"(x=1)", 1}}));
  EXPECT_EQ(distribution(m, "(x=1)", "a"), (Distribution{{"(x=0)", 1}}));
  EXPECT_EQ(distribution(m, "(x=1)", "b"), (Distribution{{"(x=2)", 1}}));
  EXPECT_EQ(distribution(m, "(x=2)", "a"), (Distribution{{"(x=0)", 1}}));
  EXPECT_EQ(distribution(m, "(x=2)", "[0]"),
            (Distribution{{"(x=0)", Rational(3, 4)}, {"(x=1)", Rational(1, 4)}}));
  const model::StateIndex x1 = state_named(m, "(x=1)");
  EXPECT_EQ(m.reward(0, x1, 1), 3);
  EXPECT_EQ(m.reward(0, x1, 0), Rational(1, 7));
  EXPECT_EQ(m.reward(0, state_named(m, "(x=2)"), 1), 3);
  EXPECT_EQ(m.reward(0, state_named(m, "(x=0)"), 0), 0);
}

// Past 2^16 choices the stream's action count runs ahead of the actions found (doubling, 4
// here once `c` is found) and is set to the true count (3) at the end.
TEST(PrismProgram, ActionsFoundAfterManyStatesAreNumberedAsFound) {
  const Loaded loaded = load(R"(
mdp
module m
  x : [0..69999] init 0;
  [a] x < 69999 -> (x'=x+1);
  [b] x > 69990 -> 0.5 : (x'=0) + 0.5 : (x'=x);
  [c] x = 69999 -> (x'=1);
endmodule
)");
  ASSERT_TRUE(loaded.model) << loaded.messages;
  const model::ExplicitModel& m = *loaded.model;
  EXPECT_EQ(m.actions, (std::vector<std::string>{"a", "b", "c"}));
  EXPECT_EQ(model::find_structural_problem(m), std::nullopt);
  using Distribution = std::map<std::string, Rational>;
  EXPECT_EQ(distribution(m, "(x=69990)", "a"), (Distribution{{"(x=69991)", 1}}));
  EXPECT_EQ(distribution(m, "(x=69995)", "b"),
            (Distribution{{"(x=0)", Rational(1, 2)}, {"(x=69995)", Rational(1, 2)}}));
  EXPECT_EQ(distribution(m, "(x=69999)", "c"), (Distribution{{"(x=1)", 1}}));
  EXPECT_EQ(distribution(m, "(x=69999)", "a"), Distribution{});
  EXPECT_EQ(m.contexts[0].transitions->num_enabled_choices(), 69999U + 9 + 1);
}

// The copy reads the formula's expansion renamed: next is mod(y + 1, N + 1) in module two.
TEST(PrismProgram, RenamedModulesConstantsAndFormulas) {
  const Loaded loaded = load(R"(
mdp
const int N;
const double q = 1/4;
formula next = mod(x + 1, N + 1);
module one
  x : [0..N] init 0;
  [tick] true -> q : (x'=next) + 1 - q : true;
endmodule
module two = one [x=y, q=r] endmodule
const double r = 1/2;
)",
                             "N=2");
  ASSERT_TRUE(loaded.model) << loaded.messages;
  const model::ExplicitModel& m = *loaded.model;
  EXPECT_EQ(m.num_states(), 9U);
  EXPECT_EQ(distribution(m, "(x=0,y=0)", "tick"),
            (std::map<std::string, Rational>{{"(x=0,y=0)", Rational(3, 8)},
                                             {"(x=0,y=1)", Rational(3, 8)},
                                             {"(x=1,y=0)", Rational(1, 8)},
                                             {"(x=1,y=1)", Rational(1, 8)}}));
}

// Everything two explicit models are made of: states (names, initial), actions,
// transitions and labels.
void expect_same_model(const model::ExplicitModel& a, const model::ExplicitModel& b) {
  ASSERT_EQ(a.num_states(), b.num_states());
  for (model::StateIndex s = 0; s < a.num_states(); ++s)
    EXPECT_EQ(a.states.name(s), b.states.name(s));
  EXPECT_EQ(a.states.initial, b.states.initial);
  EXPECT_EQ(a.actions, b.actions);
  const model::TransitionMatrix& x = *a.contexts.at(0).transitions;
  const model::TransitionMatrix& y = *b.contexts.at(0).transitions;
  EXPECT_EQ(x.num_enabled_choices(), y.num_enabled_choices());
  ASSERT_EQ(x.num_edges(), y.num_edges());
  for (model::StateIndex s = 0; s < a.num_states(); ++s) {
    for (model::ActionIndex act = 0; act < a.num_actions(); ++act) {
      ASSERT_EQ(x.enabled(s, act), y.enabled(s, act));
      if (!x.enabled(s, act)) continue;
      ASSERT_EQ(x.edges_end(s, act) - x.edges_begin(s, act),
                y.edges_end(s, act) - y.edges_begin(s, act));
      for (auto e = x.edges_begin(s, act), f = y.edges_begin(s, act); e < x.edges_end(s, act);
           ++e, ++f) {
        EXPECT_EQ(x.edge_target[e], y.edge_target[f]);
        EXPECT_EQ(a.values[x.edge_probability[e]], b.values[y.edge_probability[f]]);
      }
    }
  }
  EXPECT_EQ(a.labels.names, b.labels.names);
  EXPECT_EQ(a.labels.begin, b.labels.begin);
  EXPECT_EQ(a.labels.label, b.labels.label);
}

// PRISM expands formulas before renaming modules, so a renamed copy reads its formulas over
// the renamed variables: the same model as with every formula written out (issue 37). The
// copy used to read f over x, the original's variable: another model (equality), or an
// update out of range (the comparison, f true while y is already 2).
TEST(PrismProgram, FormulasInARenamedModuleReadTheRenamedVariables) {
  const Loaded equality = load(R"(
mdp
formula f = x = 0;
module m1
  x : [0..2] init 0;
  [] f -> 1/2 : (x'=1) + 1/2 : (x'=2);
  [] !f -> (x'=0);
endmodule
module m2 = m1 [x=y] endmodule
)");
  const Loaded equality_written_out = load(R"(
mdp
module m1
  x : [0..2] init 0;
  [] x = 0 -> 1/2 : (x'=1) + 1/2 : (x'=2);
  [] !(x = 0) -> (x'=0);
endmodule
module m2
  y : [0..2] init 0;
  [] y = 0 -> 1/2 : (y'=1) + 1/2 : (y'=2);
  [] !(y = 0) -> (y'=0);
endmodule
)");
  ASSERT_TRUE(equality.model) << equality.messages;
  ASSERT_TRUE(equality_written_out.model) << equality_written_out.messages;
  expect_same_model(*equality.model, *equality_written_out.model);

  // Nested formulas too: g uses f, and both read y in the copy.
  const Loaded comparison = load(R"(
dtmc
formula f = x < 2;
formula g = f | false;
module m1
  x : [0..2] init 0;
  [] g -> (x'=x+1);
  [] !g -> true;
endmodule
module m2 = m1 [x=y] endmodule
label "both" = !g & y = 2;
)");
  const Loaded comparison_written_out = load(R"(
dtmc
module m1
  x : [0..2] init 0;
  [] (x < 2) | false -> (x'=x+1);
  [] !((x < 2) | false) -> true;
endmodule
module m2
  y : [0..2] init 0;
  [] (y < 2) | false -> (y'=y+1);
  [] !((y < 2) | false) -> true;
endmodule
label "both" = !((x < 2) | false) & y = 2;
)");
  ASSERT_TRUE(comparison.model) << comparison.messages;
  ASSERT_TRUE(comparison_written_out.model) << comparison_written_out.messages;
  EXPECT_EQ(comparison.model->num_states(), 9U);
  expect_same_model(*comparison.model, *comparison_written_out.model);
}

// PRISM: "Formula f cannot be renamed since formulas are expanded before module renaming".
TEST(PrismProgram, AFormulaCannotBeRenamed) {
  const Loaded loaded = load(R"(
mdp
formula f = x = 0;
module m1
  x : [0..1] init 0;
  [] f -> (x'=1);
endmodule
module m2 = m1 [x=y, f=g] endmodule
)");
  EXPECT_FALSE(loaded.model);
  EXPECT_NE(loaded.messages.find("test.pm:8:22: error: formula 'f' cannot be renamed: formulas "
                                 "are expanded before renaming"),
            std::string::npos)
      << loaded.messages;
}

TEST(PrismProgram, BooleansInitBlocksAndFunctions) {
  const Loaded loaded = load(R"(
dtmc
global done : bool;
module m
  k : [0..8];
  [] !done & k < 8 -> (k'=min(8, pow(2, k) + floor(k/2))) & (done'=k=3);
  [] done | k = 8 -> true;
endmodule
init k <= 1 & !done endinit
)");
  ASSERT_TRUE(loaded.model) << loaded.messages;
  const model::ExplicitModel& m = *loaded.model;
  EXPECT_EQ(m.states.initial.size(), 2U);
  // k: 0 -> 1 -> 2 -> 5 (done stays false until leaving k=3, which is never reached).
  EXPECT_EQ(distribution(m, "(done=0,k=2)", "[0]"),
            (std::map<std::string, Rational>{{"(done=0,k=5)", 1}}));
  EXPECT_EQ(distribution(m, "(done=0,k=5)", "[0]"),
            (std::map<std::string, Rational>{{"(done=0,k=8)", 1}}));
}

TEST(PrismProgram, ConstantsOnTheCommandLineAreCheckedAgainstTheProgram) {
  const std::string program =
      "dtmc\nconst int N;\nconst bool b = true;\nmodule m\n"
      "  x : [0..N] init 0;\n  [] true -> true;\nendmodule\n";
  EXPECT_TRUE(load(program, "N=3").model);
  EXPECT_NE(load(program).messages.find("constant 'N' has no value"), std::string::npos);
  EXPECT_NE(load(program, "N=1.5").messages.find("constant 'N' is an int"), std::string::npos);
  EXPECT_NE(load(program, "N=3,M=2").messages.find("the program has no constant 'M'"),
            std::string::npos);
  EXPECT_NE(load(program, "N=3,b=false").messages.find("so --const cannot set it"),
            std::string::npos);
  EXPECT_NE(load(program, "N").messages.find("expected NAME=VALUE"), std::string::npos);
}

TEST(PrismProgram, CyclesAndBlowUpsAreErrorsNotHangs) {
  EXPECT_NE(load("dtmc\nconst int a = b;\nconst int b = a;\n").messages.find("in terms of itself"),
            std::string::npos);
  EXPECT_NE(load("dtmc\nformula f = g;\nformula g = f;\nmodule m x : [0..1]; [] f -> true; "
                 "endmodule\n")
                .messages.find("uses itself"),
            std::string::npos);
  // Each formula uses the one before twice: expanded, the last would have 2^22 nodes.
  std::string doubling =
      "dtmc\nmodule m x : [0..1]; [] f22 > 0 -> true; endmodule\nformula f0 = x;\n";
  for (int i = 1; i <= 22; ++i)
    doubling += "formula f" + std::to_string(i) + " = f" + std::to_string(i - 1) + " + f" +
                std::to_string(i - 1) + ";\n";
  EXPECT_NE(load(doubling).messages.find("nodes once its formulas are expanded"),
            std::string::npos);
  EXPECT_NE(
      load("dtmc\nconst int a = " + std::string(500, '(') + "1" + std::string(500, ')') + ";\n")
          .messages.find("nested more than"),
      std::string::npos);
}

// Inputs whose every later pass would recurse as deep as they are long, or never end: each is
// a located error (the fuzz target feeds such inputs too).
TEST(PrismProgram, DepthAndSizeAreBoundedWhereTheyWouldOverflowTheStack) {
  const std::string module = "module m x : [0..1]; [] true -> true; endmodule\n";
  std::string sum = "dtmc\nconst int a = 1";
  for (int i = 0; i < 100000; ++i)
    sum += "+1";
  EXPECT_NE(load(sum + ";\n" + module).messages.find("too long or nested too deeply"),
            std::string::npos);

  std::string formulas = "dtmc\n" + module + "formula g0 = x;\n";
  for (int i = 1; i <= 40; ++i)
    formulas += "formula g" + std::to_string(i) + " = g" + std::to_string(i - 1) + " + 1;\n";
  formulas += "label \"deep\" = g40 > 0;\n";
  EXPECT_NE(load(formulas).messages.find("formulas nested more than 24 deep"), std::string::npos);

  std::string forward = "dtmc\n" + module;
  for (int i = 0; i < 300; ++i)
    forward += "const int c" + std::to_string(i) + " = c" + std::to_string(i + 1) + " + 1;\n";
  forward += "const int c300 = 0;\n";
  EXPECT_NE(load(forward).messages.find("in terms of later ones more than 200 deep"),
            std::string::npos);

  std::string many = "mdp\n";
  for (int i = 0; i < 1100; ++i)
    many += "module m" + std::to_string(i) + " endmodule\n";
  EXPECT_NE(load(many).messages.find("more than 1024 modules"), std::string::npos);

  // 30 modules that synchronise on `a`, each with two outcomes: 2^30 combined.
  std::string wide = "mdp\n";
  for (int i = 0; i < 30; ++i) {
    const std::string v = "v" + std::to_string(i);
    wide += "module n" + std::to_string(i) + " " + v + " : [0..1]; [a] true -> 1/2 : (" + v +
            "'=0) + 1/2 : (" + v + "'=1); endmodule\n";
  }
  EXPECT_NE(load(wide).messages.find("combined outcomes"), std::string::npos);
}

TEST(PrismProgram, ProbabilitiesThatDependOnTheStateAreCheckedInEachState) {
  const Loaded loaded = load(R"(
dtmc
module m
  x : [0..2] init 0;
  [] true -> x/4 : (x'=min(x+1,2)) + 1/2 : true;
endmodule
)");
  ASSERT_FALSE(loaded.model);
  EXPECT_NE(loaded.messages.find("in state (x=0) the probabilities sum to 1/2"), std::string::npos)
      << loaded.messages;
}

// PRISM's grammar: < <= > >= bind tighter than = and !=, and => groups to the left.
TEST(PrismProgram, OperatorsBindAsInPrismsGrammar) {
  const Loaded loaded = load(R"(
dtmc
module m
  x : [0..1] init 0;
  [] true = 1 < 2 -> (x'=1);
endmodule
label "left" = false => false => false;
label "compared" = 1 < 2 = 2 < 3;
)");
  ASSERT_TRUE(loaded.model) << loaded.messages;
  const model::ExplicitModel& m = *loaded.model;
  EXPECT_EQ(distribution(m, "(x=0)", "[0]"), (std::map<std::string, Rational>{{"(x=1)", 1}}));
  // (false => false) => false is false; false => (false => false) would be true.
  EXPECT_EQ(labels_of(m, "(x=1)"), std::vector<std::string>{"compared"});
  EXPECT_NE(load("dtmc\nmodule m x : [0..1]; [] x = 1 < 2 -> true; endmodule\n")
                .messages.find("'=' compares a int with a bool"),
            std::string::npos);
}

// func(NAME, args) calls each function docs/formats.md lists, as PRISM's old syntax does.
TEST(PrismProgram, FuncCallsEveryListedFunction) {
  const Loaded loaded = load(R"(
dtmc
module m
  a : [0..9] init func(min, 3, 2);
  b : [0..9] init func(max, 3, 2, 4);
  c : [0..9] init func(floor, 5/2);
  d : [0..9] init func(ceil, 5/2);
  e : [0..9] init func(pow, 2, 3);
  f : [0..9] init func(mod, 7, 3);
  [] true -> true;
endmodule
)");
  ASSERT_TRUE(loaded.model) << loaded.messages;
  EXPECT_EQ(loaded.model->states.name(loaded.model->states.initial.at(0)),
            "(a=2,b=4,c=2,d=3,e=8,f=1)");
  EXPECT_NE(load("dtmc\nmodule m x : [0..1] init func(sqrt, 1); [] true -> true; endmodule\n")
                .messages.find("unknown function 'sqrt'"),
            std::string::npos);
}

// PRISM's mod refuses a divisor that is not positive: in a constant, when the program is
// checked; in an expression over the state, in the state where it happens.
TEST(PrismProgram, ModNeedsAPositiveDivisor) {
  const Loaded constant = load(
      "dtmc\nmodule m x : [0..3] init mod(7, -3); [] true -> true; "
      "endmodule\n");
  EXPECT_FALSE(constant.model);
  EXPECT_NE(constant.messages.find("test.pm:2:26: error: mod(7, -3): the divisor must be positive"),
            std::string::npos)
      << constant.messages;
  const Loaded state = load(R"(
dtmc
module m
  x : [0..3] init 0;
  [] true -> (x'=mod(7, x - 1));
endmodule
)");
  EXPECT_FALSE(state.model);
  EXPECT_NE(state.messages.find("mod(7, -1): the divisor must be positive"), std::string::npos)
      << state.messages;
  EXPECT_NE(state.messages.find("(x=0)"), std::string::npos) << state.messages;
}

// PRISM: "There must be at least one module", "There must be at least one variable".
TEST(PrismProgram, AProgramNeedsAModuleAndAVariable) {
  for (const char* text : {"", "// nothing but a comment\n", "mdp\n", "dtmc\nconst int N = 2;\n"}) {
    const Loaded loaded = load(text);
    EXPECT_FALSE(loaded.model) << text;
    EXPECT_NE(loaded.messages.find("error: the program declares no module"), std::string::npos)
        << loaded.messages;
  }
  EXPECT_NE(load("").messages.find("test.pm:1:1: error:"), std::string::npos);
  const Loaded no_variable = load("mdp\nmodule m [] true -> true; endmodule\n");
  EXPECT_FALSE(no_variable.model);
  EXPECT_NE(no_variable.messages.find("test.pm:1:1: error: the program declares no variable"),
            std::string::npos)
      << no_variable.messages;
}

// A labelled command synchronises; PRISM lets none of them update a global, so two modules
// cannot both write it in one step with the module order choosing the winner.
TEST(PrismProgram, SynchronisedCommandsCannotUpdateAGlobal) {
  const Loaded loaded = load(R"(
mdp
global g : [0..2] init 0;
module a
  x : [0..1] init 0;
  [s] x = 0 -> (x'=1) & (g'=1);
endmodule
module b
  y : [0..1] init 0;
  [s] y = 0 -> (y'=1) & (g'=2);
  [] y = 1 -> (g'=0);
endmodule
)");
  EXPECT_FALSE(loaded.model);
  EXPECT_NE(loaded.messages.find("test.pm:6:26: error: global variable 'g' cannot be updated by "
                                 "a command with action 's'"),
            std::string::npos)
      << loaded.messages;
  EXPECT_NE(loaded.messages.find("test.pm:10:26: error: global variable 'g'"), std::string::npos)
      << loaded.messages;
  EXPECT_EQ(loaded.messages.find("test.pm:11:"), std::string::npos) << loaded.messages;
}

}  // namespace
}  // namespace oasis::prism
