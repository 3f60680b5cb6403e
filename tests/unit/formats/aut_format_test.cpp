#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include <gtest/gtest.h>
#include <unistd.h>

#include "../../support/scratch_directory.hpp"
#include "formats/aut_label.hpp"
#include "formats/aut_reader.hpp"
#include "formats/aut_writer.hpp"
#include "formats/model_file.hpp"

namespace oasis::formats {
namespace {

namespace fs = std::filesystem;
using model::ExplicitModel;

// A SourceManager and a DiagnosticEngine whose output the tests inspect.
class AutTest : public ::testing::Test {
 protected:
  std::optional<ExplicitModel> read(const std::string& text, const std::string& path = "x.aut") {
    const FileId file = sources_.add(path, text);
    std::optional<ExplicitModel> model = read_aut(file, diagnostics_, options_);
    if (model) {
      const auto problem = model::find_structural_problem(*model);
      EXPECT_FALSE(problem) << *problem;
    }
    return model;
  }
  [[nodiscard]] std::string output() const { return out_.str(); }
  [[nodiscard]] bool reported(const std::string& fragment) const {
    return output().find(fragment) != std::string::npos;
  }

  SourceManager sources_;
  std::ostringstream out_;
  DiagnosticEngine diagnostics_{sources_, out_};
  ReadOptions options_;
};

Rational probability(const ExplicitModel& model, model::StateIndex s, const std::string& action,
                     model::StateIndex target) {
  const auto& matrix = *model.contexts[0].transitions;
  const auto a = static_cast<model::ActionIndex>(
      std::find(model.actions.begin(), model.actions.end(), action) - model.actions.begin());
  if (a == model.num_actions()) return 0;
  for (auto e = matrix.edges_begin(s, a); e < matrix.edges_end(s, a); ++e) {
    if (matrix.edge_target[e] == target) return model.values[matrix.edge_probability[e]];
  }
  return 0;
}

Rational reward(const ExplicitModel& model, model::StateIndex s, const std::string& action) {
  const auto a = static_cast<model::ActionIndex>(
      std::find(model.actions.begin(), model.actions.end(), action) - model.actions.begin());
  return model.reward(0, s, a);
}

TEST_F(AutTest, ReadsProbabilisticTransitions) {
  const auto model = read(
      "des (0,4,3)\n"
      "(0,\"a\",1 1/3 2)\n"
      "(0,b,2)\n"
      "( 1 , \"a|reward(5/2)\" , 0 1/2 1 1/4 2 )\r\n"
      "(2,\"b\",2)");
  ASSERT_TRUE(model) << output();
  EXPECT_EQ(output(), "");
  EXPECT_EQ(model->name, "x");
  EXPECT_EQ(model->num_states(), 3U);
  EXPECT_EQ(model->actions, (std::vector<std::string>{"a", "b"}));
  EXPECT_EQ(model->states.initial, (std::vector<model::StateIndex>{0}));
  ASSERT_EQ(model->contexts.size(), 1U);
  EXPECT_EQ(model->contexts[0].name, "default");
  EXPECT_EQ(model->contexts[0].transitions->num_edges(), 7U);
  EXPECT_EQ(probability(*model, 0, "a", 1), Rational(1, 3));
  EXPECT_EQ(probability(*model, 0, "a", 2), Rational(2, 3));
  EXPECT_EQ(probability(*model, 1, "a", 0), Rational(1, 2));
  EXPECT_EQ(probability(*model, 1, "a", 1), Rational(1, 4));
  EXPECT_EQ(probability(*model, 1, "a", 2), Rational(1, 4));
  EXPECT_EQ(reward(*model, 1, "a"), Rational(5, 2));
  EXPECT_EQ(reward(*model, 0, "a"), 0);
  EXPECT_EQ(model->states.names.size(), 0U);
  for (auto id : model->contexts[0].rewards.state)
    EXPECT_EQ(id, RationalPool::kZero);
}

TEST_F(AutTest, RewardsOnlyInLabelsLeaveChoiceTableEmptyWhenZero) {
  const auto model = read("des (0,1,1)\n(0,\"tau\",0)\n");
  ASSERT_TRUE(model) << output();
  EXPECT_TRUE(model->contexts[0].rewards.choice.empty());
}

TEST_F(AutTest, RepeatedTargetsAreMerged) {
  const auto model = read("des (0,1,2)\n(0,\"a\",1 1/2 1)\n");
  ASSERT_TRUE(model) << output();
  EXPECT_EQ(probability(*model, 0, "a", 1), 1);
  EXPECT_EQ(model->contexts[0].transitions->num_edges(), 1U);
}

TEST_F(AutTest, UnsortedFileGivesTheSameMatrix) {
  const auto sorted = read("des (0,3,3)\n(0,\"a\",1)\n(0,\"b\",2 1/2 1)\n(2,\"a\",0)\n");
  const auto shuffled = read("des (0,3,3)\n(2,\"a\",0)\n(0,\"b\",2 1/2 1)\n(0,\"a\",1)\n");
  ASSERT_TRUE(sorted && shuffled) << output();
  const auto& x = *sorted->contexts[0].transitions;
  const auto& y = *shuffled->contexts[0].transitions;
  EXPECT_EQ(x.choice_begin, y.choice_begin);
  EXPECT_EQ(x.edge_target, y.edge_target);
  EXPECT_EQ(probability(*shuffled, 0, "b", 1), Rational(1, 2));
}

TEST_F(AutTest, ProbabilisticInitialStateKeepsItsSupport) {
  const auto model = read("des (2 1/2 0,1,3)\n(0,\"a\",1)\n");
  ASSERT_TRUE(model) << output();
  EXPECT_EQ(model->states.initial, (std::vector<model::StateIndex>{0, 2}));
  EXPECT_TRUE(reported("x.aut:1:6: warning: the initial state is a distribution")) << output();
}

TEST_F(AutTest, EndOfTransmissionEndsTheFile) {
  const auto model = read("des (0,1,1)\n(0,\"a\",0)\n\x04garbage after the file\n");
  ASSERT_TRUE(model) << output();
}

TEST_F(AutTest, SecondDistributionForTheSameActionIsNotAnMdp) {
  const auto model = read(
      "des (0,4,4)\n"
      "(0,\"a\",1)\n"
      "(3,\"a\",1)\n"
      "(3,\"b\",2)\n"
      "(3,\"a|reward(1)\",2)\n");
  EXPECT_FALSE(model);
  EXPECT_TRUE(
      reported("x.aut:5:4: error: state 3 already has a distribution for action 'a' "
               "(line 3); an MDP allows one per action"))
      << output();
  EXPECT_TRUE(reported("x.aut:3:4: note: the first distribution of state 3 for action 'a' is here"))
      << output();
}

struct ErrorCase {
  const char* text;
  const char* expected;
};

class AutErrorTest : public AutTest, public ::testing::WithParamInterface<ErrorCase> {};

TEST_P(AutErrorTest, ReportsAtTheRightPlace) {
  EXPECT_FALSE(read(GetParam().text));
  EXPECT_TRUE(reported(GetParam().expected)) << output();
}

INSTANTIATE_TEST_SUITE_P(
    Errors, AutErrorTest,
    ::testing::Values(
        ErrorCase{"hello\n",
                  "x.aut:1:1: error: expected the header 'des (initial, transitions, states)'"},
        ErrorCase{"des 0,1,1)\n", "x.aut:1:5: error: expected '(' after 'des'"},
        ErrorCase{"des (0,1,1\n", "x.aut:1:11: error: expected ')' to close the header"},
        ErrorCase{"des (0,1,1) x\n", "x.aut:1:13: error: unexpected text after the header"},
        ErrorCase{"des (0,1,0)\n", "x.aut:1:10: error: the header declares no states"},
        ErrorCase{"des (5,0,2)\n",
                  "x.aut:1:6: error: state 5 is out of range: the header declares 2 states"},
        ErrorCase{"des (0,1,2)\n(0,\"a\",2)\n",
                  "x.aut:2:8: error: state 2 is out of range: the header declares 2 states"},
        ErrorCase{"des (0,1,2)\n(7,\"a\",1)\n",
                  "x.aut:2:2: error: state 7 is out of range: the header declares 2 states"},
        ErrorCase{"des (0,1,2)\n(0,\"a\",1 1/2 99999999999999999999999)\n",
                  "x.aut:2:14: error: state 99999999999999999999999 is out of range"},
        ErrorCase{"des (0,1,2)\n0,\"a\",1)\n",
                  "x.aut:2:1: error: expected '(' to start a transition"},
        ErrorCase{"des (0,1,2)\n(0 \"a\",1)\n",
                  "x.aut:2:4: error: expected ',' after the source state"},
        ErrorCase{"des (0,1,2)\n(0,\"a,1)\n", "x.aut:2:4: error: unterminated label"},
        ErrorCase{"des (0,1,2)\n(0,\"\",1)\n", "x.aut:2:4: error: empty label"},
        ErrorCase{"des (0,1,2)\n(0,\"a\",1 1 0)\n",
                  "x.aut:2:12: error: expected '/' in the probability"},
        ErrorCase{"des (0,1,2)\n(0,\"a\",1 1/0 0)\n",
                  "x.aut:2:10: error: probability has a zero denominator"},
        ErrorCase{"des (0,1,2)\n(0,\"a\",1 0/3 0)\n",
                  "x.aut:2:10: error: probability must be positive"},
        ErrorCase{"des (0,1,3)\n(0,\"a\",1 2/3 0 1/2 2)\n",
                  "x.aut:2:16: error: probabilities before the last target sum to 7/6 (1.16667), "
                  "more than 1"},
        ErrorCase{"des (0,1,3)\n(0,\"a\",1 1/2 0 1/2 2)\n",
                  "x.aut:2:16: error: probabilities reach 1 before the last target"},
        ErrorCase{"des (0,1,2)\n(0,\"a\",1 1/2)\n", "x.aut:2:13: error: expected a state number"},
        ErrorCase{"des (0,1,2)\n(0,\"a\",1\n",
                  "x.aut:2:9: error: expected ')' to close the transition"},
        ErrorCase{"des (0,1,2)\n(0,\"a\",1) (1,\"a\",0)\n",
                  "x.aut:2:11: error: unexpected text after the transition"},
        ErrorCase{"des (0,2,2)\n(0,\"a\",1)\n",
                  "x.aut:1:8: error: the header declares 2 transitions but the file has 1"},
        ErrorCase{"des (0,1,2)\n(0,\"a\",1)\n(1,\"a\",0)\n",
                  "x.aut:1:8: error: the header declares 1 transitions but the file has 2"},
        ErrorCase{"des (0,1,2)\n(0,\"a|reward(x)\",1)\n",
                  "x.aut:2:4: error: reward 'x' in label 'a|reward(x)' is not a number"},
        ErrorCase{"des (0,1,2)\n(0,\"reward(1)\",1)\n",
                  "x.aut:2:4: error: label 'reward(1)' has a reward but no action"},
        ErrorCase{"des (0,1,2)\n(0,\"a|reward(1)|reward(2)\",1)\n",
                  "x.aut:2:4: error: label 'a|reward(1)|reward(2)' has two reward parts"}));

TEST_F(AutTest, StateLimitIsEnforcedBeforeAllocating) {
  options_.max_states = 10;
  EXPECT_FALSE(read("des (0,0,11)\n"));
  EXPECT_TRUE(
      reported("x.aut:1:10: error: the header declares 11 states, more than the limit "
               "of 10 (raise it with --max-states)"))
      << output();
}

// Issue 41: without --max-states, only 32-bit state numbers bound the count, and no option
// raises that.
TEST_F(AutTest, TheStateIndexIsTheHardLimit) {
  EXPECT_FALSE(read("des (0,0,4294967295)\n"));
  EXPECT_TRUE(
      reported("x.aut:1:10: error: the header declares 4294967295 states, more than the "
               "4294967294 that oasis can number (states are numbered with 32 bits; no "
               "option raises this)"))
      << output();
}

// Issue 41: a header declaring more than reading it could fit is refused at the header, before
// the body is read (its bad line is never reported), naming the option that raises the budget.
TEST_F(AutTest, AHeaderBeyondTheMemoryBudgetIsRefusedBeforeTheBody) {
  options_.memory_budget = std::uint64_t{1} << 30;
  // 24 + 8 bytes per transition (one edge each, at least) and 4 per state: 3.24e11 bytes.
  EXPECT_FALSE(read("des (0,10000000000,1000000000)\n(0,\"a\",1)\n(0,\"b\",x)\n"));
  EXPECT_TRUE(
      reported("x.aut:1:8: error: the header declares 10000000000 transitions and "
               "1000000000 states: reading it takes at least 301.7 GiB, more than the "
               "memory budget of 1.0 GiB (raise it with --memory-budget)"))
      << output();
  EXPECT_FALSE(reported("x.aut:3:")) << output();
}

TEST_F(AutTest, AModelWithinTheMemoryBudgetIsReadAsWithout) {
  const std::string text = "des (0,3,2)\n(0,\"a\",1)\n(1,\"a\",0 1/4 1)\n(1,\"b\",1)\n";
  const std::optional<ExplicitModel> without = read(text);
  ASSERT_TRUE(without) << output();
  options_.memory_budget = std::uint64_t{16} << 20;
  const std::optional<ExplicitModel> with = read(text, "y.aut");
  ASSERT_TRUE(with) << output();
  EXPECT_EQ(with->num_states(), without->num_states());
  EXPECT_EQ(with->actions, without->actions);
  EXPECT_EQ(probability(*with, 1, "a", 0), Rational(1, 4));
  EXPECT_EQ(output(), "");
}

TEST_F(AutTest, SeveralErrorsInOneRun) {
  EXPECT_FALSE(read("des (0,3,2)\n(0,\"a\",5)\n(1,\"a\",1 1/0 0)\n(9,\"a\",0)\n"));
  EXPECT_TRUE(reported("x.aut:2:8: error:")) << output();
  EXPECT_TRUE(reported("x.aut:3:10: error:")) << output();
  EXPECT_TRUE(reported("x.aut:4:2: error:")) << output();
  EXPECT_EQ(diagnostics_.error_count(), 3U);
}

TEST_F(AutTest, StopsAtTheErrorLimit) {
  std::string text = "des (0,100,2)\n";
  for (int i = 0; i < 100; ++i)
    text += "(5,\"a\",0)\n";
  EXPECT_FALSE(read(text));
  EXPECT_TRUE(diagnostics_.should_stop());
  EXPECT_TRUE(reported("too many errors emitted")) << output();
}

// --- labels -----------------------------------------------------------------------------

TEST(AutLabel, FormatsInMcrl2SortOrder) {
  EXPECT_EQ(format_aut_label("a", Rational(0)), "a");
  EXPECT_EQ(format_aut_label("a", Rational(1, 2)), "a|reward(1/2)");
  EXPECT_EQ(format_aut_label("wait", Rational(-3)), "reward(-3)|wait");
  EXPECT_EQ(format_aut_label("a|z", Rational(2)), "a|reward(2)|z");
}

TEST(AutLabel, ParsesBackWhatItFormats) {
  for (const std::string action : {"a", "wait", "send(1,2)", "a|z", "tau", "myreward(3)"}) {
    for (const Rational& reward : {Rational(0), Rational(7, 3), Rational(-1, 2), Rational(5)}) {
      std::string error;
      const auto parsed = parse_aut_label(format_aut_label(action, reward), error);
      ASSERT_TRUE(parsed) << error;
      EXPECT_EQ(parsed->action, action);
      EXPECT_EQ(parsed->reward, reward);
    }
  }
}

TEST(AutLabel, ParsesMcrl2SortedAndSpacedForms) {
  std::string error;
  auto parsed = parse_aut_label("reward(0.25)|sleep", error);
  ASSERT_TRUE(parsed) << error;
  EXPECT_EQ(parsed->action, "sleep");
  EXPECT_EQ(parsed->reward, Rational(1, 4));
  parsed = parse_aut_label("a | reward( 1/3 )", error);
  ASSERT_TRUE(parsed) << error;
  EXPECT_EQ(parsed->action, "a");
  EXPECT_EQ(parsed->reward, Rational(1, 3));
}

TEST(AutLabel, RejectsUnwritableActions) {
  EXPECT_TRUE(aut_action_problem(""));
  EXPECT_TRUE(aut_action_problem("a\"b"));
  EXPECT_TRUE(aut_action_problem("a(b"));
  EXPECT_TRUE(aut_action_problem("a|"));
  EXPECT_TRUE(aut_action_problem("a|reward(1)"));
  EXPECT_FALSE(aut_action_problem("send(1,2)|b"));
}

// --- round trips ----------------------------------------------------------------------

// Compares two models by action name (the .aut reader numbers actions by first appearance):
// same states, initial states, enabled choices, edges with exact probabilities, and R(s, a)
// on every enabled choice.
void expect_same_model(const ExplicitModel& expected, const ExplicitModel& actual) {
  ASSERT_EQ(expected.num_states(), actual.num_states());
  EXPECT_EQ(expected.states.initial, actual.states.initial);
  const auto& x = *expected.contexts[0].transitions;
  const auto& y = *actual.contexts[0].transitions;
  EXPECT_EQ(x.num_enabled_choices(), y.num_enabled_choices());
  EXPECT_EQ(x.num_edges(), y.num_edges());
  for (model::ActionIndex a = 0; a < expected.num_actions(); ++a) {
    const auto found = std::find(actual.actions.begin(), actual.actions.end(), expected.actions[a]);
    const auto b = static_cast<model::ActionIndex>(found - actual.actions.begin());
    for (model::StateIndex s = 0; s < expected.num_states(); ++s) {
      if (!x.enabled(s, a)) {
        EXPECT_TRUE(b == actual.num_actions() || !y.enabled(s, b));
        continue;
      }
      ASSERT_LT(b, actual.num_actions()) << expected.actions[a];
      ASSERT_TRUE(y.enabled(s, b)) << "state " << s << " action " << expected.actions[a];
      ASSERT_EQ(x.edges_end(s, a) - x.edges_begin(s, a), y.edges_end(s, b) - y.edges_begin(s, b));
      for (auto e = x.edges_begin(s, a), f = y.edges_begin(s, b); e < x.edges_end(s, a); ++e, ++f) {
        EXPECT_EQ(x.edge_target[e], y.edge_target[f]);
        EXPECT_EQ(expected.values[x.edge_probability[e]], actual.values[y.edge_probability[f]]);
      }
      EXPECT_EQ(expected.reward(0, s, a), actual.reward(0, s, b)) << "state " << s;
    }
  }
}

// A random MDP with fractional probabilities, state and choice rewards (some negative).
ExplicitModel random_model(std::uint32_t num_states, std::uint32_t num_actions, unsigned seed) {
  std::mt19937 random(seed);
  ExplicitModel model;
  model.name = "random";
  model.states.size = num_states;
  model.states.initial = {0};
  for (std::uint32_t a = 0; a < num_actions; ++a)
    model.actions.push_back("act" + std::to_string(a));
  model::TransitionBuilder builder(num_states, num_actions);
  model::Context context;
  context.name = "default";
  context.rewards.state.resize(num_states);
  context.rewards.choice.assign(std::size_t{num_states} * num_actions, RationalPool::kZero);
  const int denominators[] = {1, 2, 3, 4, 7, 10, 12};
  for (model::StateIndex s = 0; s < num_states; ++s) {
    context.rewards.state[s] =
        model.values.intern(Rational(static_cast<long>(random() % 5) - 1, 1 + random() % 3));
    for (model::ActionIndex a = 0; a < num_actions; ++a) {
      if (a > 0 && random() % 3 == 0) continue;  // action 0 always enabled: no deadlocks
      const int denominator = denominators[random() % 7];
      int left = denominator;
      while (left > 0) {
        const int share =
            left == 1 ? 1 : 1 + static_cast<int>(random() % static_cast<unsigned>(left));
        builder.add(s, a, random() % num_states, model.values.intern(Rational(share, denominator)));
        left -= share;
      }
      context.rewards.choice[std::size_t{s} * num_actions + a] =
          model.values.intern(Rational(static_cast<long>(random() % 7) - 2, 1 + random() % 4));
    }
  }
  context.transitions =
      std::make_shared<const model::TransitionMatrix>(builder.finish(model.values));
  model.contexts.push_back(std::move(context));
  return model;
}

class AutFileTest : public AutTest {
 protected:
  test::ScratchDirectory scratch_{"oasis_aut"};
  const std::filesystem::path& directory_ = scratch_.path();

  std::optional<ExplicitModel> round_trip(const ExplicitModel& model) {
    const std::string path = (directory_ / "model.aut").string();
    std::string error;
    EXPECT_TRUE(write_aut_file(model, 0, path, error)) << error;
    auto read_back = read_model_file(path, sources_, diagnostics_, options_);
    if (read_back) {
      const auto problem = model::find_structural_problem(*read_back);
      EXPECT_FALSE(problem) << *problem;
    }
    return read_back;
  }
  static std::string contents(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }
};

TEST_F(AutFileTest, WritesTheDocumentedForm) {
  const auto model = read("des (0,3,3)\n(0,\"b\",2 1/3 1)\n(0,\"a|reward(-1/2)\",1)\n(2,a,2)\n");
  ASSERT_TRUE(model) << output();
  const std::string path = (directory_ / "out.aut").string();
  std::string error;
  ASSERT_TRUE(write_aut_file(*model, 0, path, error)) << error;
  EXPECT_EQ(contents(path),
            "des (0,3,3)\n"
            "(0,\"b\",1 2/3 2)\n"
            "(0,\"a|reward(-1/2)\",1)\n"
            "(2,\"a\",2)\n");
}

TEST_F(AutFileTest, RandomModelRoundTrips) {
  const ExplicitModel model = random_model(300, 4, 12345);
  ASSERT_FALSE(model::find_structural_problem(model));
  const auto read_back = round_trip(model);
  ASSERT_TRUE(read_back) << output();
  expect_same_model(model, *read_back);
  // Writing what was read gives the same bytes: the output is deterministic.
  const std::string first = contents(directory_ / "model.aut");
  std::string error;
  ASSERT_TRUE(write_aut_file(*read_back, 0, (directory_ / "again.aut").string(), error)) << error;
  EXPECT_EQ(contents(directory_ / "again.aut"), first);
}

TEST_F(AutFileTest, SeveralInitialStatesRoundTripAsASet) {
  ExplicitModel model = random_model(20, 2, 7);
  model.states.initial = {0, 4, 9};
  const auto read_back = round_trip(model);
  ASSERT_TRUE(read_back) << output();
  EXPECT_EQ(read_back->states.initial, model.states.initial);
}

TEST_F(AutFileTest, UnwritableActionNameLeavesNoFile) {
  ExplicitModel model = random_model(5, 2, 3);
  model.actions[1] = "bad\"name";
  std::string error;
  const std::string path = (directory_ / "bad.aut").string();
  EXPECT_FALSE(write_aut_file(model, 0, path, error));
  EXPECT_NE(error.find("contains a quote"), std::string::npos) << error;
  EXPECT_TRUE(fs::is_empty(directory_));
}

TEST_F(AutFileTest, MissingFileIsAFileError) {
  EXPECT_FALSE(
      read_model_file((directory_ / "none.aut").string(), sources_, diagnostics_, options_));
  EXPECT_TRUE(reported("none.aut: error: no such file or directory")) << output();
}

// --- hostile input ----------------------------------------------------------------------

std::string sample(const std::string& name) {
  std::ifstream in(std::string(OASIS_SOURCE_DIR) + "/tests/data/formats/" + name, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST_F(AutTest, SampleFileReads) {
  const auto model = read(sample("coin.aut"), "coin.aut");
  ASSERT_TRUE(model) << output();
  EXPECT_GT(model->num_states(), 0U);
}

TEST(AutFuzz, TruncatedAndFlippedSamplesNeverCrash) {
  const std::string text = sample("coin.aut");
  ASSERT_FALSE(text.empty());
  std::mt19937 random(99);
  for (std::size_t length = 0; length <= text.size(); ++length) {
    SourceManager sources;
    std::ostringstream out;
    DiagnosticEngine diagnostics(sources, out);
    const auto model = read_aut(sources.add("t.aut", text.substr(0, length)), diagnostics, {});
    if (model) {
      EXPECT_FALSE(model::find_structural_problem(*model));
    }
  }
  const char replacements[] = {'\0', '(', ')', ',', '"', '/',   '|',
                               '\n', ' ', '9', '0', 'x', '\x04'};
  for (int round = 0; round < 2000; ++round) {
    std::string flipped = text;
    for (int k = 0; k < 1 + round % 4; ++k) {
      flipped[random() % flipped.size()] = replacements[random() % sizeof replacements];
    }
    SourceManager sources;
    std::ostringstream out;
    DiagnosticEngine diagnostics(sources, out);
    const auto model = read_aut(sources.add("f.aut", flipped), diagnostics, {});
    if (model) {
      EXPECT_FALSE(model::find_structural_problem(*model));
    } else {
      EXPECT_TRUE(diagnostics.has_errors());
    }
  }
}

}  // namespace
}  // namespace oasis::formats
