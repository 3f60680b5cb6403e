#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include <gtest/gtest.h>
#include <unistd.h>

#include "../../support/scratch_directory.hpp"
#include "bisim/refinement.hpp"
#include "formats/explicit_reader.hpp"
#include "formats/explicit_writer.hpp"
#include "formats/model_file.hpp"

namespace oasis::formats {
namespace {

namespace fs = std::filesystem;
using model::ExplicitModel;

std::string sample_path(const std::string& name) {
  return std::string(OASIS_SOURCE_DIR) + "/tests/data/formats/" + name;
}

std::string contents(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

model::ActionIndex action_named(const ExplicitModel& model, const std::string& name) {
  return static_cast<model::ActionIndex>(
      std::find(model.actions.begin(), model.actions.end(), name) - model.actions.begin());
}

Rational probability(const ExplicitModel& model, model::StateIndex s, const std::string& action,
                     model::StateIndex target) {
  const auto& matrix = *model.contexts[0].transitions;
  const auto a = action_named(model, action);
  if (a == model.num_actions()) return 0;
  for (auto e = matrix.edges_begin(s, a); e < matrix.edges_end(s, a); ++e) {
    if (matrix.edge_target[e] == target) return model.values[matrix.edge_probability[e]];
  }
  return 0;
}

// Inline texts for the files of one model, read with read_prism.
class PrismTest : public ::testing::Test {
 protected:
  std::optional<ExplicitModel> read(const std::string& tra, const std::string& sta = "",
                                    const std::string& lab = "", const std::string& srew = "",
                                    const std::string& trew = "") {
    PrismFiles files;
    files.transitions = sources_.add("x.tra", tra);
    if (!sta.empty()) files.states = sources_.add("x.sta", sta);
    if (!lab.empty()) files.labels = sources_.add("x.lab", lab);
    if (!srew.empty()) files.state_rewards = sources_.add("x.srew", srew);
    if (!trew.empty()) files.transition_rewards = sources_.add("x.trew", trew);
    std::optional<ExplicitModel> model = read_prism(files, diagnostics_, options_);
    if (model && !options_.tolerance) check(*model);
    return model;
  }
  static void check(const ExplicitModel& model) {
    const auto problem = model::find_structural_problem(model);
    EXPECT_FALSE(problem) << *problem;
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

TEST_F(PrismTest, ReadsTheSampleWithItsSiblings) {
  const auto model = read_model_file(sample_path("robot.tra"), sources_, diagnostics_, options_);
  ASSERT_TRUE(model) << output();
  check(*model);
  EXPECT_EQ(output(), "");
  EXPECT_EQ(model->name, "robot");
  EXPECT_EQ(model->num_states(), 4U);
  EXPECT_EQ(model->actions, (std::vector<std::string>{"go", "stay", "[0]", "[1]"}));
  EXPECT_EQ(model->states.variables, (std::vector<std::string>{"x", "done"}));
  EXPECT_EQ(model->states.valuations, (std::vector<std::int64_t>{0, 0, 1, 0, -2, 0, 3, 1}));
  EXPECT_EQ(model->states.name(2), "(x=-2,done=0)");
  EXPECT_EQ(model->states.initial, (std::vector<model::StateIndex>{0}));
  EXPECT_EQ(probability(*model, 2, "go", 3), Rational(4, 5));
  EXPECT_EQ(probability(*model, 1, "[1]", 2), Rational(3, 4));
  EXPECT_EQ(model->contexts[0].transitions->num_edges(), 9U);
  EXPECT_EQ(model->reward(0, 0, action_named(*model, "go")), 2);
  EXPECT_EQ(model->reward(0, 0, action_named(*model, "stay")), 0);
  EXPECT_EQ(model->reward(0, 1, action_named(*model, "[0]")), Rational(3, 2));
  EXPECT_EQ(model->reward(0, 2, action_named(*model, "go")), Rational(5, 4));
}

TEST_F(PrismTest, WithoutSiblingsStateZeroIsInitial) {
  const auto model = read("2 2 2\n0 0 1 1 a\n1 0 1 1\n");
  ASSERT_TRUE(model) << output();
  EXPECT_EQ(model->states.initial, (std::vector<model::StateIndex>{0}));
  EXPECT_TRUE(model->states.variables.empty());
  EXPECT_TRUE(model->contexts[0].rewards.choice.empty());
}

TEST_F(PrismTest, InitialLinesInTheTransitionsFile) {
  const auto model = read("# Transitions (MDP)\n3 1 1\n- - 2 -\n- - 1 -\n0 0 1 1\n");
  ASSERT_TRUE(model) << output();
  EXPECT_EQ(model->states.initial, (std::vector<model::StateIndex>{1, 2}));
}

TEST_F(PrismTest, FractionsAndExponentsAreExact) {
  const auto model = read("2 1 3\n0 0 0 1/3\n0 0 1 1/6\n0 0 1 5e-1\n");
  ASSERT_TRUE(model) << output();
  EXPECT_EQ(probability(*model, 0, "[0]", 1), Rational(2, 3));
}

TEST_F(PrismTest, SumOffByRoundingNeedsTolerance) {
  const std::string tra = "2 1 3\n0 0 0 0.3333333333\n0 0 1 0.3333333333\n0 0 1 0.3333333333\n";
  EXPECT_FALSE(read(tra));
  EXPECT_TRUE(
      reported("x.tra:2:1: error: probabilities of state 0, choice 0 sum to "
               "9999999999/10000000000 (1), not 1"))
      << output();
  options_.tolerance = Rational(1, 1000000);
  const auto model = read(tra);
  ASSERT_TRUE(model) << output();
  // Kept as written: the model is only approximately stochastic, and the check says so.
  EXPECT_EQ(probability(*model, 0, "[0]", 0), Rational(3333333333, 10000000000));
  const auto problem = model::find_structural_problem(*model);
  ASSERT_TRUE(problem);
  EXPECT_NE(problem->find("sums to 9999999999/10000000000"), std::string::npos) << *problem;
}

TEST_F(PrismTest, SecondChoiceWithTheSameActionIsNotAnMdp) {
  EXPECT_FALSE(read("4 3 3\n0 0 1 1 a\n3 0 1 1 a\n3 1 2 1 a\n"));
  EXPECT_TRUE(
      reported("x.tra:4:1: error: state 3 has two choices with action 'a' (choices 0 and 1, "
               "lines 3 and 4); an MDP allows one per action"))
      << output();
  EXPECT_TRUE(reported("x.tra:3:1: note: choice 0 of state 3 is here")) << output();
}

TEST_F(PrismTest, UnlabelledChoicesAreDistinctActions) {
  const auto model = read("1 2 2\n0 0 0 1\n0 1 0 1\n");
  ASSERT_TRUE(model) << output();
  EXPECT_EQ(model->actions, (std::vector<std::string>{"[0]", "[1]"}));
}

// A Markov chain (two header numbers, no choice column) is an MDP with one action, "[0]":
// each state's rows are its one distribution, their action labels set aside, and a .trew
// reward belongs to that one choice.
TEST_F(PrismTest, ReadsAMarkovChainAsAnMdpWithOneAction) {
  const auto model = read("3 4\n0 1 0.5 a\n0 2 1/2 b\n1 1 1\n2 0 1 c\n", "", "", "3 1\n2 7\n",
                          "3 2\n0 1 2\n0 2 2\n");
  ASSERT_TRUE(model) << output();
  EXPECT_EQ(model->actions, (std::vector<std::string>{"[0]"}));
  EXPECT_EQ(probability(*model, 0, "[0]", 1), Rational(1, 2));
  EXPECT_EQ(probability(*model, 0, "[0]", 2), Rational(1, 2));
  EXPECT_EQ(probability(*model, 1, "[0]", 1), 1);
  EXPECT_EQ(probability(*model, 2, "[0]", 0), 1);
  EXPECT_EQ(model->reward(0, 2, 0), 7);  // the state reward of state 2
  EXPECT_EQ(model->reward(0, 0, 0), 2);  // the transition reward of state 0's one choice
  EXPECT_EQ(model->reward(0, 1, 0), 0);
}

// Bisimulation of the one-action MDP is the chain's lumping: 1 and 2 both reach 3 surely.
TEST_F(PrismTest, AMarkovChainQuotientsAsItsLumping) {
  const auto chain = read("4 5\n0 1 0.5\n0 2 0.5\n1 3 1\n2 3 1\n3 3 1\n", "", "", "4 1\n3 1\n");
  ASSERT_TRUE(chain) << output();
  const model::Partition blocks = bisim::coarsest_bisimulation(*chain, 0);
  EXPECT_EQ(blocks.num_blocks, 3U);
  EXPECT_EQ(blocks.block_of[1], blocks.block_of[2]);
  EXPECT_NE(blocks.block_of[0], blocks.block_of[1]);
}

TEST_F(PrismTest, AMarkovChainsStateWithRowsThatDisagreeOnItsRewardIsRefused) {
  EXPECT_FALSE(read("2 3\n0 1 0.5\n0 0 0.5\n1 0 1\n", "", "", "", "2 2\n0 1 2\n0 0 3\n"));
  EXPECT_TRUE(reported("x.trew:3:1: error: rows of state 0, choice 0 give different rewards"))
      << output();
}

struct ErrorCase {
  const char* tra;
  const char* sta;
  const char* lab;
  const char* srew;
  const char* trew;
  const char* expected;
};

class PrismErrorTest : public PrismTest, public ::testing::WithParamInterface<ErrorCase> {};

TEST_P(PrismErrorTest, ReportsAtTheRightPlace) {
  const ErrorCase& c = GetParam();
  EXPECT_FALSE(read(c.tra, c.sta, c.lab, c.srew, c.trew));
  EXPECT_TRUE(reported(c.expected)) << output();
}

constexpr const char* kTra = "2 2 3\n0 0 1 0.5 a\n0 0 0 0.5 a\n1 0 1 1\n";

// Issue 41: a header declaring more than reading it could fit is refused before the rows are
// read, naming the option.
TEST(PrismFormat, AHeaderBeyondTheMemoryBudgetIsRefusedBeforeTheRows) {
  SourceManager sources;
  std::ostringstream out;
  DiagnosticEngine diagnostics(sources, out);
  PrismFiles files;
  files.transitions = sources.add("x.tra", "1000000000 2000000000 3000000000\n0 0 1 x\n");
  ReadOptions options;
  options.memory_budget = std::uint64_t{1} << 30;
  EXPECT_FALSE(read_prism(files, diagnostics, options));
  EXPECT_NE(out.str().find("x.tra:1:1: error: the header declares 1000000000 states, 2000000000 "
                           "choices and 3000000000 transitions: reading it takes at least "
                           "70.8 GiB, more than the memory budget of 1.0 GiB (raise it with "
                           "--memory-budget)"),
            std::string::npos)
      << out.str();
  EXPECT_EQ(out.str().find("x.tra:2:"), std::string::npos) << out.str();
}

INSTANTIATE_TEST_SUITE_P(
    Errors, PrismErrorTest,
    ::testing::Values(
        ErrorCase{"", "", "", "", "", "x.tra:1:1: error: empty transitions file"},
        ErrorCase{"2 1 1 1\n0 0 1 1\n", "", "", "", "",
                  "x.tra:1:1: error: expected the header 'states choices transitions' of an "
                  "MDP, or 'states transitions' of a Markov chain"},
        ErrorCase{"2 3\n0 1 1\n1 0 1\n0 0 1\n", "", "", "", "",
                  "x.tra:4:1: error: more rows of state 0, choice 0 after rows of other choices"},
        ErrorCase{"2 2\n0 1 0.5\n1 1 1\n", "", "", "", "",
                  "x.tra:2:1: error: probabilities of state 0, choice 0 sum to 1/2 (0.5), not 1"},
        ErrorCase{"2 2\n0 1 1\n1 0 1\n", "", "", "", "2 1\n0 0 1 2\n",
                  "x.trew:2:7: error: unexpected text after the reward"},
        ErrorCase{"2 1 x\n", "", "", "", "",
                  "x.tra:1:1: error: expected the header 'states choices transitions'"},
        ErrorCase{"0 0 0\n", "", "", "", "", "x.tra:1:1: error: the header declares no states"},
        ErrorCase{"2 1 1\n0 0 2 1\n", "", "", "", "",
                  "x.tra:2:5: error: state 2 is out of range: the model has 2 states"},
        ErrorCase{"2 1 1\n0 0 1 abc\n", "", "", "", "",
                  "x.tra:2:7: error: probability 'abc' is not a number"},
        ErrorCase{"2 1 1\n0 0 1 0\n", "", "", "", "",
                  "x.tra:2:7: error: probability must be positive"},
        ErrorCase{"2 1 1\n0 0 1 1 a b\n", "", "", "", "",
                  "x.tra:2:11: error: unexpected text after the action"},
        ErrorCase{
            "2 1 2\n0 0 1 0.5 a\n0 0 0 0.5 b\n", "", "", "", "",
            "x.tra:3:11: error: state 0, choice 0 has action 'b' here but action 'a' on line 2"},
        ErrorCase{
            "2 1 2\n0 0 1 0.5 a\n0 0 0 0.5\n", "", "", "", "",
            "x.tra:3:10: error: state 0, choice 0 has no action here but action 'a' on line 2"},
        ErrorCase{"2 1 2\n0 0 1 0.9\n", "", "", "", "",
                  "x.tra:2:1: error: probabilities of state 0, choice 0 sum to 9/10 (0.9), not 1"},
        ErrorCase{"2 3 3\n0 0 1 1\n1 0 0 1\n0 0 0 1\n", "", "", "", "",
                  "x.tra:4:1: error: more rows of state 0, choice 0 after rows of other choices"},
        ErrorCase{"2 5 3\n0 0 1 0.5 a\n0 0 0 0.5 a\n1 0 1 1\n", "", "", "", "",
                  "x.tra:1:1: error: the header declares 5 choices but the file has 2"},
        ErrorCase{"2 2 9\n0 0 1 0.5 a\n0 0 0 0.5 a\n1 0 1 1\n", "", "", "", "",
                  "x.tra:1:1: error: the header declares 9 transitions but the file has 3"},
        ErrorCase{kTra, "x,y)\n", "", "", "",
                  "x.sta:1:1: error: expected the variables '(x,y,...)'"},
        ErrorCase{kTra, "(x)\n0:(1)\n0:(2)\n", "", "", "",
                  "x.sta:3:1: error: state 0 is listed twice"},
        ErrorCase{
            kTra, "(x)\n0:(1)\n", "", "", "",
            "x.sta:1:1: error: 1 of the 2 states have no valuation here, the first being state 1"},
        ErrorCase{kTra, "(x,y)\n0:(1)\n1:(1,2)\n", "", "", "",
                  "x.sta:2:5: error: expected ',' between values"},
        ErrorCase{kTra, "(x)\n0:(1,2)\n1:(1)\n", "", "", "",
                  "x.sta:2:5: error: expected ')' after 1 value, as in the header"},
        ErrorCase{kTra, "(x)\n0:(yes)\n1:(1)\n", "", "", "",
                  "x.sta:2:4: error: value 'yes' is not an integer or boolean"},
        ErrorCase{kTra, "", "0=\"init\" 2=\"x\"\n", "", "",
                  "x.lab:1:10: error: expected label index 1"},
        ErrorCase{kTra, "", "0=\"init\"\n0: 3\n", "", "",
                  "x.lab:2:4: error: label 3 is not declared in the first line"},
        ErrorCase{kTra, "", "0=\"init\"\n5: 0\n", "", "",
                  "x.lab:2:1: error: state 5 is out of range"},
        // A label is declared once: two "init"s would each give initial states, and a
        // repeated name could not be told apart by --respect-labels.
        ErrorCase{kTra, "", "0=\"init\" 1=\"init\"\n0: 0 1\n", "", "",
                  "x.lab:1:13: error: label 'init' is declared twice (as label 0 and label 1)"},
        ErrorCase{kTra, "", "0=\"init\" 1=\"a\" 2=\"a\"\n0: 0\n", "", "",
                  "x.lab:1:19: error: label 'a' is declared twice (as label 1 and label 2)"},
        ErrorCase{kTra, "", "0=\"init\" 1=\"\"\n0: 0\n", "", "",
                  "x.lab:1:13: error: empty label name"},
        ErrorCase{kTra, "", "", "3 1\n0 1\n", "",
                  "x.srew:1:1: error: the header declares 3 states but the transitions file has 2"},
        ErrorCase{kTra, "", "", "2 2\n0 1\n", "",
                  "x.srew:1:1: error: the header declares 2 rewards but the file has 1"},
        ErrorCase{kTra, "", "", "2 2\n0 1\n0 2\n", "",
                  "x.srew:3:1: error: state 0 has a second reward"},
        ErrorCase{kTra, "", "", "2 1\n1 one\n", "",
                  "x.srew:2:3: error: reward 'one' is not a number"},
        ErrorCase{kTra, "", "", "", "2 2 1\n1 3 1 1\n",
                  "x.trew:2:1: error: state 1 has no choice 3 in the transitions file"},
        ErrorCase{kTra, "", "", "", "2 2 2\n0 0 1 1\n0 0 0 2\n",
                  "x.trew:3:1: error: rows of state 0, choice 0 give different rewards"}));

// A NUL cannot be part of a label name (it would cut the name short in every message and
// file that shows it): a located error at the NUL.
TEST_F(PrismTest, ALabelNameWithANulIsRefused) {
  using namespace std::string_literals;
  const std::string lab = "0=\"init\" 1=\"a\0b\"\n0: 0\n"s;
  EXPECT_FALSE(read(kTra, "", lab));
  EXPECT_TRUE(reported("x.lab:1:14: error: a label name cannot hold a NUL character")) << output();
}

// --- round trips -----------------------------------------------------------------------

void expect_same_model(const ExplicitModel& expected, const ExplicitModel& actual) {
  ASSERT_EQ(expected.num_states(), actual.num_states());
  EXPECT_EQ(expected.states.initial, actual.states.initial);
  EXPECT_EQ(expected.states.variables, actual.states.variables);
  EXPECT_EQ(expected.states.valuations, actual.states.valuations);
  const auto& x = *expected.contexts[0].transitions;
  const auto& y = *actual.contexts[0].transitions;
  EXPECT_EQ(x.num_enabled_choices(), y.num_enabled_choices());
  EXPECT_EQ(x.num_edges(), y.num_edges());
  for (model::ActionIndex a = 0; a < expected.num_actions(); ++a) {
    const auto b = action_named(actual, expected.actions[a]);
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

// A random MDP with variables, fractional and decimal probabilities, state and choice
// rewards, and some actions named like PRISM's unlabelled choices.
ExplicitModel random_model(std::uint32_t num_states, unsigned seed) {
  std::mt19937 random(seed);
  ExplicitModel model;
  model.states.size = num_states;
  model.states.initial = {0, num_states / 2};
  model.states.variables = {"x", "y"};
  for (model::StateIndex s = 0; s < num_states; ++s) {
    model.states.valuations.push_back(s);
    model.states.valuations.push_back(static_cast<std::int64_t>(random() % 7) - 3);
  }
  model.actions = {"north", "south", "[0]", "[1]", "[7]"};
  const auto k = model.num_actions();
  model::TransitionBuilder builder(num_states, k);
  model::Context context;
  context.name = "default";
  context.rewards.state.resize(num_states);
  context.rewards.choice.assign(std::size_t{num_states} * k, RationalPool::kZero);
  const int denominators[] = {1, 2, 3, 4, 8, 10, 12};
  for (model::StateIndex s = 0; s < num_states; ++s) {
    context.rewards.state[s] =
        model.values.intern(Rational(static_cast<long>(random() % 5) - 1, 1 + random() % 4));
    for (model::ActionIndex a = 0; a < k; ++a) {
      if (random() % 2 == 0 && !(a == 0 && s % 5 != 0)) continue;  // a few deadlocks
      const int denominator = denominators[random() % 7];
      for (int left = denominator; left > 0;) {
        const int share =
            left == 1 ? 1 : 1 + static_cast<int>(random() % static_cast<unsigned>(left));
        builder.add(s, a, random() % num_states, model.values.intern(Rational(share, denominator)));
        left -= share;
      }
      if (random() % 3 == 0) {
        context.rewards.choice[std::size_t{s} * k + a] =
            model.values.intern(Rational(1 + random() % 9, 1 + random() % 3));
      }
    }
  }
  context.transitions =
      std::make_shared<const model::TransitionMatrix>(builder.finish(model.values));
  model.contexts.push_back(std::move(context));
  return model;
}

class PrismFileTest : public PrismTest {
 protected:
  test::ScratchDirectory scratch_{"oasis_prism"};
  const std::filesystem::path& directory_ = scratch_.path();
  [[nodiscard]] std::string base() const { return (directory_ / "model").string(); }
};

TEST_F(PrismFileTest, RandomModelRoundTrips) {
  const ExplicitModel model = random_model(300, 2024);
  ASSERT_FALSE(model::find_structural_problem(model));
  std::string error;
  ASSERT_TRUE(write_prism(model, 0, base(), error)) << error;
  for (const char* extension : {".tra", ".sta", ".lab", ".srew", ".trew"}) {
    EXPECT_TRUE(fs::exists(base() + extension)) << extension;
  }
  const auto read_back = read_model_file(base() + ".tra", sources_, diagnostics_, options_);
  ASSERT_TRUE(read_back) << output();
  check(*read_back);
  expect_same_model(model, *read_back);
  // Writing again gives the same bytes (choices are ordered by action index, so this holds
  // for the same model, not for the re-read one whose actions are numbered by appearance).
  ASSERT_TRUE(write_prism(model, 0, (directory_ / "again.tra").string(), error)) << error;
  for (const char* extension : {".tra", ".sta", ".lab", ".srew", ".trew"}) {
    EXPECT_TRUE(contents(base() + extension) ==
                contents((directory_ / "again").string() + extension))
        << extension;
  }
}

TEST_F(PrismFileTest, AMarkovChainIsWrittenBackAsAOneActionMdp) {
  const auto chain = read("3 4\n0 1 0.5\n0 2 0.5\n1 1 1\n2 0 1\n");
  ASSERT_TRUE(chain) << output();
  std::string error;
  ASSERT_TRUE(write_prism(*chain, 0, base(), error)) << error;
  const std::string tra = contents(base() + ".tra");
  EXPECT_EQ(tra.rfind("3 3 4\n", 0), 0U) << tra;  // states, choices, transitions
  const auto read_back = read_model_file(base() + ".tra", sources_, diagnostics_, options_);
  ASSERT_TRUE(read_back) << output();
  expect_same_model(*chain, *read_back);
}

TEST_F(PrismFileTest, SampleRoundTripsAndStaysPrismReadable) {
  const auto model = read_model_file(sample_path("robot.tra"), sources_, diagnostics_, options_);
  ASSERT_TRUE(model) << output();
  std::string error;
  ASSERT_TRUE(write_prism(*model, 0, base(), error)) << error;
  const std::string tra = contents(base() + ".tra");
  EXPECT_EQ(tra.find('['), std::string::npos) << tra;  // "[j]" choices are written unlabelled
  EXPECT_NE(tra.find("2 0 3 0.8 go\n"), std::string::npos) << tra;  // decimals where exact
  const auto read_back = read_model_file(base() + ".tra", sources_, diagnostics_, options_);
  ASSERT_TRUE(read_back) << output();
  expect_same_model(*model, *read_back);
}

TEST_F(PrismFileTest, StaleSiblingsAreRemoved) {
  ExplicitModel model = random_model(10, 5);
  std::string error;
  ASSERT_TRUE(write_prism(model, 0, base(), error)) << error;
  model.states.variables.clear();
  model.states.valuations.clear();
  model.contexts[0].rewards.choice.clear();
  ASSERT_TRUE(write_prism(model, 0, base() + ".tra", error)) << error;
  EXPECT_FALSE(fs::exists(base() + ".sta"));
  EXPECT_FALSE(fs::exists(base() + ".trew"));
  const auto read_back = read_model_file(base() + ".tra", sources_, diagnostics_, options_);
  ASSERT_TRUE(read_back) << output();
  expect_same_model(model, *read_back);
}

TEST_F(PrismFileTest, BadActionNameWritesNothing) {
  ExplicitModel model = random_model(10, 6);
  model.actions[0] = "two words";
  std::string error;
  EXPECT_FALSE(write_prism(model, 0, base(), error));
  EXPECT_NE(error.find("has blanks"), std::string::npos) << error;
  EXPECT_TRUE(fs::is_empty(directory_));
}

TEST_F(PrismFileTest, UnknownExtensionIsAFileError) {
  EXPECT_FALSE(read_model_file(base() + ".xyz", sources_, diagnostics_, options_));
  EXPECT_TRUE(reported("model.xyz: error: unknown model file type '.xyz'")) << output();
}

TEST(PrismFuzz, TruncatedAndFlippedSamplesNeverCrash) {
  const std::string names[] = {"robot.tra", "robot.sta", "robot.lab", "robot.srew", "robot.trew"};
  std::string texts[5];
  for (int i = 0; i < 5; ++i)
    texts[i] = contents(sample_path(names[i]));
  const auto attempt = [&](int damaged, const std::string& text) {
    SourceManager sources;
    std::ostringstream out;
    DiagnosticEngine diagnostics(sources, out);
    FileId ids[5];
    for (int i = 0; i < 5; ++i)
      ids[i] = sources.add(names[i], i == damaged ? text : texts[i]);
    const PrismFiles files{ids[0], ids[1], ids[2], ids[3], ids[4]};
    ReadOptions options;
    options.max_states = 1000;
    const auto model = read_prism(files, diagnostics, options);
    if (model) {
      EXPECT_FALSE(model::find_structural_problem(*model));
    } else {
      EXPECT_TRUE(diagnostics.has_errors());
    }
  };
  std::mt19937 random(17);
  const char replacements[] = {'\0', ' ', '\n', '#', '-', ':', '(',
                               ')',  ',', '"',  '9', '0', '.', 'x'};
  for (int damaged = 0; damaged < 5; ++damaged) {
    const std::string& text = texts[damaged];
    for (std::size_t length = 0; length <= text.size(); ++length)
      attempt(damaged, text.substr(0, length));
    for (int round = 0; round < 400; ++round) {
      std::string flipped = text;
      for (int k = 0; k < 1 + round % 3; ++k) {
        flipped[random() % flipped.size()] = replacements[random() % sizeof replacements];
      }
      attempt(damaged, flipped);
    }
  }
}

}  // namespace
}  // namespace oasis::formats
