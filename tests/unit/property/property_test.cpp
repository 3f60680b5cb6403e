// The property language: PRISM's syntax parsed, every operator answered on small programs whose
// values are worked out by hand (Knuth and Yao's die, a two-action MDP with an end
// component), and every error located, as docs/properties.md promises.

#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "prism/load_program.hpp"
#include "property/evaluator.hpp"
#include "property/parser.hpp"

namespace oasis::property {
namespace {

// Knuth and Yao's die with a reward of 1 per coin flip ("flips"): 11/3 flips expected.
constexpr const char* kDie = R"(dtmc
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
const int six = 6;
formula done = s=7;
label "one" = s=7 & d=1;
rewards "flips" s<7 : 1; endrewards
)";

// From state 0, action `stay` loops (an end component) and `go` reaches goal or fail with
// probability 1/3 and 2/3. Pmax(F goal) = 1/3 (the loop never gets there), Pmin = 0.
constexpr const char* kChoice = R"(mdp
module m
  x : [0..2] init 0;
  [stay] x=0 -> (x'=0);
  [go] x=0 -> 1/3 : (x'=1) + 2/3 : (x'=2);
  [] x>0 -> (x'=x);
endmodule
label "goal" = x=1;
rewards "cost" [go] true : 2; [stay] true : 1; endrewards
)";

struct Answers {
  std::vector<std::optional<Answer>> answers;
  std::string messages;
};

Answers query(const char* program, const std::string& properties,
              modelcheck::Mode mode = modelcheck::Mode::kExact, bool bisimulation = false,
              bool schedulers = false) {
  const std::string rewards = "all";
  SourceManager sources;
  std::ostringstream out;
  DiagnosticEngine diagnostics(sources, out);
  prism::LoadOptions load;
  load.rewards = *model::LabelSelection::parse(rewards);
  Names names;
  load.names = &names;
  const auto model =
      prism::load_program_text(sources.add("test.pm", program), "test", diagnostics, load);
  EXPECT_TRUE(model) << out.str();
  Answers run;
  if (!model) return run;
  const PropertiesFile file = parse_file(sources.add("--prop", properties), diagnostics);
  modelcheck::Options options;
  options.mode = mode;
  options.want_scheduler = schedulers;
  Evaluator evaluator(*model, names, file, diagnostics, options);
  evaluator.use_bisimulation(bisimulation);
  for (const Property& property : file.properties)
    run.answers.push_back(evaluator.answer(property));
  run.messages = out.str();
  return run;
}

Rational exact(const Answers& run, std::size_t i) {
  EXPECT_LT(i, run.answers.size()) << run.messages;
  if (i >= run.answers.size() || !run.answers[i]) {
    ADD_FAILURE() << "property " << i << " has no answer: " << run.messages;
    return -1;
  }
  return run.answers[i]->value.exact;
}

TEST(Properties, TheDieAnswersExactly) {
  const Answers run = query(kDie,
                            "P=? [F s=7&d=1]; P=? [F \"one\"]; P=? [F done & d=six];"
                            "P=? [G d!=2]; P=? [F<=3 d=1]; P=? [X s=1]; P=? [!(d=3) U d=2];"
                            "R{\"flips\"}=? [F s=7]; R=? [C<=2]; R=? [I=3]");
  EXPECT_EQ(exact(run, 0), Rational(1, 6));
  EXPECT_EQ(exact(run, 1), Rational(1, 6));
  EXPECT_EQ(exact(run, 2), Rational(1, 6));
  EXPECT_EQ(exact(run, 3), Rational(5, 6));
  EXPECT_EQ(exact(run, 4), Rational(1, 8));  // 0 -> 1 -> 3 -> (7, d=1) only
  EXPECT_EQ(exact(run, 5), Rational(1, 2));
  EXPECT_EQ(exact(run, 6), Rational(1, 6));
  EXPECT_EQ(exact(run, 7), Rational(11, 3));
  EXPECT_EQ(exact(run, 8), Rational(2));     // the first two steps always flip
  EXPECT_EQ(exact(run, 9), Rational(1, 4));  // still flipping at step 3: s=1 or s=2
}

TEST(Properties, SoundIntervalsContainTheExactValues) {
  const std::string properties = "P=? [F s=7&d=1]; R{\"flips\"}=? [F s=7]; P=? [G d!=2]";
  const Answers exact_run = query(kDie, properties);
  const Answers sound_run = query(kDie, properties, modelcheck::Mode::kSound);
  ASSERT_EQ(sound_run.answers.size(), 3u) << sound_run.messages;
  for (std::size_t i = 0; i < 3; ++i) {
    ASSERT_TRUE(sound_run.answers[i]) << sound_run.messages;
    const modelcheck::Value& v = sound_run.answers[i]->value;
    const double truth = exact(exact_run, i).get_d();
    EXPECT_LE(v.lower, truth) << i;
    EXPECT_GE(v.upper, truth) << i;
    EXPECT_LE(v.upper - v.lower, 1e-6) << i;
  }
}

TEST(Properties, BoundsAndFiltersGiveVerdicts) {
  const Answers run = query(kDie,
                            "P>=1/6 [F \"one\"]; P>1/6 [F \"one\"]; P<0.5 [F d=1] & s=0;"
                            "filter(count, s=7); filter(forall, P>=1 [F s=7]);"
                            "filter(max, P=? [F d=1], s=3)");
  ASSERT_EQ(run.answers.size(), 6u) << run.messages;
  for (const auto& answer : run.answers)
    ASSERT_TRUE(answer) << run.messages;
  EXPECT_TRUE(run.answers[0]->verdict);
  EXPECT_FALSE(run.answers[1]->verdict);
  EXPECT_TRUE(run.answers[2]->verdict);
  EXPECT_EQ(run.answers[3]->value.exact, 6);  // over every state: s=7 with d = 1..6
  EXPECT_TRUE(run.answers[4]->verdict);
  // From s=3: x3 = 1/2 + x1/2 and x1 = x3/2, so 2/3.
  EXPECT_EQ(run.answers[5]->value.exact, Rational(2, 3));
}

TEST(Properties, AnMdpIsOptimisedBothWays) {
  const Answers run = query(kChoice,
                            "Pmax=? [F \"goal\"]; Pmin=? [F \"goal\"]; P<=1/3 [F \"goal\"];"
                            "R{\"cost\"}min=? [F x>0]; Rmax=? [F x>0]");
  EXPECT_EQ(exact(run, 0), Rational(1, 3));
  EXPECT_EQ(exact(run, 1), 0);
  ASSERT_TRUE(run.answers.at(2)) << run.messages;
  EXPECT_TRUE(run.answers[2]->verdict);
  EXPECT_EQ(exact(run, 3), 2);  // go at once
  ASSERT_TRUE(run.answers.at(4)) << run.messages;
  EXPECT_TRUE(run.answers[4]->value.infinite);  // staying forever never reaches x>0
}

TEST(Properties, TheQuotientGivesTheModelsAnswersRationalForRational) {
  const std::string die =
      "P=? [F s=7&d=1]; P=? [G d!=2]; P=? [F<=3 d=1]; P=? [X s=1]; R{\"flips\"}=? [F s=7];"
      "R=? [C<=2]; R=? [I=3]; P>=1/6 [F \"one\"]";
  const std::string choice =
      "Pmax=? [F \"goal\"]; Pmin=? [F \"goal\"]; R{\"cost\"}min=? [F x>0]; Pmax=? [F<=1 x=1]";
  for (const auto& [program, properties] : {std::pair{kDie, die}, std::pair{kChoice, choice}}) {
    const Answers plain = query(program, properties);
    const Answers reduced = query(program, properties, modelcheck::Mode::kExact, true, true);
    ASSERT_EQ(plain.answers.size(), reduced.answers.size()) << reduced.messages;
    for (std::size_t i = 0; i < plain.answers.size(); ++i) {
      ASSERT_TRUE(plain.answers[i] && reduced.answers[i]) << reduced.messages;
      EXPECT_EQ(plain.answers[i]->value.exact, reduced.answers[i]->value.exact) << i;
      EXPECT_EQ(plain.answers[i]->verdict, reduced.answers[i]->verdict) << i;
      EXPECT_NE(reduced.answers[i]->method.find("on the bisimulation quotient"), std::string::npos);
    }
  }
}

TEST(Properties, SchedulersAreReturnedAndRecheckedOnTheModel) {
  const Answers run = query(kChoice, "Pmax=? [F \"goal\"]", modelcheck::Mode::kExact, true, true);
  ASSERT_EQ(run.answers.size(), 1u);
  ASSERT_TRUE(run.answers[0] && run.answers[0]->scheduler) << run.messages;
  // In x=0 the maximum takes `go`: `stay` keeps the value 1/3 only by never reaching goal.
  const auto& actions = run.answers[0]->scheduler->action;
  ASSERT_FALSE(actions.empty());
  EXPECT_NE(run.answers[0]->method.find("re-checked on the model"), std::string::npos);
}

TEST(Properties, APropertiesFileDefinesConstantsAndLabels) {
  const Answers run = query(kDie,
                            "const int face = 2; const double half = 1/2;\n"
                            "label \"shown\" = s=7 & d=face; label \"early\" = \"shown\" & true;\n"
                            "P=? [F \"early\"]; P<half [F d=face]");
  ASSERT_EQ(run.answers.size(), 2u) << run.messages;
  EXPECT_EQ(exact(run, 0), Rational(1, 6));
  ASSERT_TRUE(run.answers[1]) << run.messages;
  EXPECT_TRUE(run.answers[1]->verdict);
  const Answers cycle = query(kDie, "label \"a\" = \"b\"; label \"b\" = \"a\"; P=? [F \"a\"]");
  ASSERT_EQ(cycle.answers.size(), 1u) << cycle.messages;
  EXPECT_FALSE(cycle.answers[0]);
  EXPECT_NE(cycle.messages.find("uses itself"), std::string::npos) << cycle.messages;
}

// The message and the place of the first error for one property.
std::string first_error(const char* program, const std::string& property) {
  const Answers run = query(program, property);
  EXPECT_FALSE(run.answers.empty() || run.answers[0]) << property;
  return run.messages.substr(0, run.messages.find('\n'));
}

TEST(Properties, ErrorsAreLocated) {
  EXPECT_EQ(first_error(kDie, "P=? [F \"seven\"]").substr(0, 40),
            "--prop:1:8: error: unknown label \"seven\"");
  EXPECT_EQ(first_error(kDie, "R{\"time\"}=? [F s=7]"),
            "--prop:1:3: error: the model has no reward structure 'time' (it has 'flips')");
  EXPECT_EQ(first_error(kDie, "Pmax=? [F s=7]"),
            "--prop:1:1: error: Pmax asks for an optimum over choices, and a Markov chain has "
            "none: write P=? instead, as PRISM requires");
  EXPECT_EQ(first_error(kDie, "P>=1.5 [F s=7]"),
            "--prop:1:4: error: a probability bound must lie in [0, 1], not 3/2 (1.5)");
  EXPECT_EQ(first_error(kChoice, "P=? [F x=1]"),
            "--prop:1:1: error: in an MDP the value depends on the scheduler: write Pmin=? or "
            "Pmax=?");
  EXPECT_EQ(first_error(kDie, "P>=0.5 [F P=? [F s=7]]"),
            "--prop:1:11: error: a query (=?) gives a number, not a state formula: compare it "
            "with a bound instead, as in P>=0.5 [ ... ]");
  EXPECT_EQ(first_error(kDie, "P=? [F<=-1 s=7]"),
            "--prop:1:9: error: a step bound must be a non-negative integer, not -1");
  EXPECT_EQ(first_error(kDie, "P=? [F t=1]"), "--prop:1:8: error: unknown name 't'");
}

TEST(Properties, SyntaxErrorsAreLocatedAndParsingGoesOn) {
  SourceManager sources;
  std::ostringstream out;
  DiagnosticEngine diagnostics(sources, out);
  const PropertiesFile file = parse_file(
      sources.add("p.props", "P=? F s=7];\nP=? [F s=7]\nR{time}=? [F s=7]"), diagnostics);
  EXPECT_EQ(file.properties.size(), 1u);
  const std::string messages = out.str();
  EXPECT_NE(messages.find("p.props:1:5: error: expected '[' to open the path formula"),
            std::string::npos)
      << messages;
  EXPECT_NE(messages.find("p.props:3:3: error: expected the reward structure's name in quotes"),
            std::string::npos)
      << messages;
}

TEST(Properties, NestingTooDeepIsRefused) {
  std::string deep;
  for (int i = 0; i < 300; ++i)
    deep += "P>=0 [F ";
  deep += "true";
  for (int i = 0; i < 300; ++i)
    deep += "]";
  SourceManager sources;
  std::ostringstream out;
  DiagnosticEngine diagnostics(sources, out);
  const PropertiesFile file = parse_file(sources.add("--prop", deep), diagnostics);
  EXPECT_TRUE(diagnostics.has_errors());
  EXPECT_NE(out.str().find("nested more than"), std::string::npos) << out.str();
}

}  // namespace
}  // namespace oasis::property
